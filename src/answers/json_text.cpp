// JSON text with every number the shortest decimal of the value meant (dragon/json.hpp).
#include "dragon/json.hpp"

#include <cmath>
#include <cstdint>
#include <cstdlib>

#include <fmt/format.h>

namespace dragon {

double meant(double v) {
    if (!std::isfinite(v) || v == 0.0) return v == 0.0 ? 0.0 : v;  // no "-0"
    // 15 significant digits hold every decimal of up to 15 digits exactly (the value typed, a
    // grid's spacing, a speed rounded to 6 decimals), and drop the last bits' noise of the
    // arithmetic that made it (0.0025 from (0.55 - 0.35) / 80); no answer is known that closely.
    return std::strtod(fmt::format("{:.15g}", v).c_str(), nullptr);
}

namespace {

// A float as the shortest decimal that reads back as the value meant (fmt's shortest form:
// nlohmann's Grisu2 is not always shortest, 0.9794349999999999 for 0.979435); whole numbers
// (within 2^53) without ".0", as JSON integers ("times":[0,300]); NaN and infinities as null.
std::string number_text(double v) {
    const double m = meant(v);
    if (!std::isfinite(m)) return "null";
    if (m == std::trunc(m) && std::abs(m) <= 0x1p53) return fmt::format("{}", static_cast<std::int64_t>(m));
    return fmt::format("{}", m);
}

// nlohmann's dump, compact or indented, with number_text for floats.
void put_json(std::string& out, const Json& v, int indent, int depth) {
    const bool pretty = indent >= 0;
    const auto newline = [&](int level) {
        if (pretty) out += '\n' + std::string(static_cast<std::size_t>(indent * level), ' ');
    };
    if (v.is_object() || v.is_array()) {
        const bool object = v.is_object();
        if (v.empty()) {
            out += object ? "{}" : "[]";
            return;
        }
        out += object ? '{' : '[';
        bool first = true;
        for (auto it = v.begin(); it != v.end(); ++it) {
            if (!first) out += ',';
            first = false;
            newline(depth + 1);
            if (object) out += Json(it.key()).dump(-1, ' ', false, Json::error_handler_t::replace) + (pretty ? ": " : ":");
            put_json(out, *it, indent, depth + 1);
        }
        newline(depth);
        out += object ? '}' : ']';
        return;
    }
    if (v.is_number_float()) out += number_text(v.get<double>());
    else out += v.dump(-1, ' ', false, Json::error_handler_t::replace);
}

}  // namespace

std::string json_text(const Json& v, int indent) {
    std::string out;
    put_json(out, v, indent, 0);
    return out;
}

}  // namespace dragon
