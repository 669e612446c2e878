#include "dragon/window.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>

#include <fmt/format.h>

namespace dragon {

std::string to_string(const Along& a) {
    if (std::isinf(a.value) && a.value > 0.0) return "open";
    return fmt::format("{} {}", a.value, a.unit == Along::Unit::metres ? "m" : "s");
}

std::optional<Along> parse_along(const std::string& text) {
    std::string number = text;
    Along::Unit unit = Along::Unit::seconds;
    const auto trim = [&] {
        while (!number.empty() && std::isspace(static_cast<unsigned char>(number.back()))) number.pop_back();
    };
    trim();
    if (!number.empty() && (number.back() == 'm' || number.back() == 's')) {
        unit = number.back() == 'm' ? Along::Unit::metres : Along::Unit::seconds;
        number.pop_back();
        trim();
    }
    char* end = nullptr;
    const double v = number.empty() ? NAN : std::strtod(number.c_str(), &end);
    if (number.empty() || end != number.c_str() + number.size() || !std::isfinite(v)) return std::nullopt;
    return Along{v, unit};
}

}  // namespace dragon
