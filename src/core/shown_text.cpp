#include "dragon/shown_text.hpp"

#include <fmt/format.h>

namespace dragon {

std::string shown_text(const std::string& text, std::size_t most) {
    std::string out;
    std::size_t shown = 0;
    for (const char c : text) {
        if (shown == most) break;
        ++shown;
        const auto u = static_cast<unsigned char>(c);
        if (c == '\n') out += "\\n";
        else if (c == '\r') out += "\\r";
        else if (c == '\t') out += "\\t";
        else if (u < 0x20 || u == 0x7f) out += fmt::format("\\x{:02x}", u);
        else out += c;
    }
    if (shown < text.size()) out += fmt::format("... ({} characters)", text.size());
    return out;
}

}  // namespace dragon
