// JSON text with every number the shortest decimal of the value meant (dragon/json.hpp).
#include "dragon/json.hpp"

#include <cmath>
#include <cstdint>
#include <cstdlib>

#include <fmt/format.h>

namespace dragon {

namespace {

// 10^0 .. 10^22: every one exactly a double (5^22 < 2^53).
constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                             1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

// The double nearest the decimal `text` (as printf's %g writes it: a sign, digits with a point,
// an exponent), as strtod reads it. Its digits, at most 15 of them, make a whole number D below
// 2^53 and its value is D * 10^e: for |e| <= 22 both factors are doubles exactly, and one
// multiplication or division, correctly rounded by IEEE 754, gives the nearest double (Clinger's
// fast path), the same bits as strtod's. Other exponents go to strtod itself. The fast path
// matters in the page: WebAssembly's strtod (musl's) works in software 128-bit arithmetic, and
// it was a third of the page's Q2 (every number of an answer is read back once).
double read_decimal(const char* text) {
    const char* p = text;
    const bool negative = *p == '-';
    if (negative || *p == '+') ++p;
    std::uint64_t digits = 0;
    int count = 0, exponent = 0;
    bool fraction = false;
    for (;; ++p) {
        if (*p >= '0' && *p <= '9') {
            digits = digits * 10 + static_cast<std::uint64_t>(*p - '0');
            if (digits != 0) ++count;
            if (fraction) --exponent;
        } else if (*p == '.' && !fraction) {
            fraction = true;
        } else {
            break;
        }
    }
    if (*p == 'e' || *p == 'E') {
        ++p;
        const bool down = *p == '-';
        if (down || *p == '+') ++p;
        int e = 0;
        for (; *p >= '0' && *p <= '9' && e < 10000; ++p) e = e * 10 + (*p - '0');
        exponent += down ? -e : e;
    }
    if (*p != '\0' || count > 15 || exponent < -22 || exponent > 22) return std::strtod(text, nullptr);
    const double d = static_cast<double>(digits);  // exact: below 10^15
    const double r = exponent >= 0 ? d * kPow10[exponent] : d / kPow10[-exponent];
    return negative ? -r : r;
}

}  // namespace

double meant(double v) {
    if (!std::isfinite(v) || v == 0.0) return v == 0.0 ? 0.0 : v;  // no "-0"
    // 15 significant digits hold every decimal of up to 15 digits exactly (the value typed, a
    // grid's spacing, a speed rounded to 6 decimals), and drop the last bits' noise of the
    // arithmetic that made it (0.0025 from (0.55 - 0.35) / 80); no answer is known that closely.
    char text[40];
    const auto end = fmt::format_to_n(text, sizeof text - 1, "{:.15g}", v);
    *end.out = '\0';
    return read_decimal(text);
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

// put_json on one line, hearing each leaf's text as it is written.
void put_json_leaves(std::string& out, const Json& v, const std::string& path,
                     const std::function<void(const std::string&, std::string_view)>& leaf) {
    if (v.is_object() && !v.empty()) {  // as put_json writes an object on one line
        out += '{';
        bool first = true;
        for (auto it = v.begin(); it != v.end(); ++it) {
            if (!first) out += ',';
            first = false;
            out += Json(it.key()).dump(-1, ' ', false, Json::error_handler_t::replace) + ':';
            put_json_leaves(out, *it, path.empty() ? it.key() : path + "." + it.key(), leaf);
        }
        out += '}';
        return;
    }
    const std::size_t start = out.size();
    put_json(out, v, -1, 0);
    leaf(path, std::string_view(out).substr(start));
}

}  // namespace

std::string json_text(const Json& v, int indent) {
    std::string out;
    put_json(out, v, indent, 0);
    return out;
}

std::string json_text_with_leaves(const Json& v,
                                  const std::function<void(const std::string& path, std::string_view text)>& leaf) {
    std::string out;
    put_json_leaves(out, v, "", leaf);
    return out;
}

}  // namespace dragon
