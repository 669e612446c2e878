#include "cli/report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>

#include <fmt/format.h>

#include "dragon/tables.hpp"

namespace dragon::cli {

std::vector<int> summary_handles(int handle_count) {
    std::vector<int> out;
    for (int h : {0, 1, 51, 101, 151, 201})
        if (h < handle_count - 1) out.push_back(h);
    out.push_back(handle_count - 1);
    return out;
}

std::string handle_name(int handle, int handle_count) {
    if (handle == 0) return "head";
    if (handle == handle_count - 1) return "tail (rear)";
    if (handle == handle_count - 2) return "tail";
    return fmt::format("body {}", handle);
}

void print_frame_table(const std::string& title, const std::vector<const Frame*>& frames) {
    if (frames.empty()) return;
    const int n = static_cast<int>(frames.front()->handles.size());
    fmt::print("{}\n{:<18}", title, "");
    for (const Frame* f : frames) fmt::print(" {:>11}", time_header(f->time));
    fmt::print("\n");
    for (int h : summary_handles(n)) {
        const std::string name = handle_name(h, n);
        fmt::print("{:<18}", name + " x (m)");
        for (const Frame* f : frames) fmt::print(" {:>11.6f}", round6(f->handles[static_cast<size_t>(h)].pos.x()));
        fmt::print("\n{:<18}", name + " y (m)");
        for (const Frame* f : frames) fmt::print(" {:>11.6f}", round6(f->handles[static_cast<size_t>(h)].pos.y()));
        fmt::print("\n");
    }
    for (int h : summary_handles(n)) {
        fmt::print("{:<18}", handle_name(h, n) + " (m/s)");
        for (const Frame* f : frames) fmt::print(" {:>11.6f}", round6(f->handles[static_cast<size_t>(h)].speed));
        fmt::print("\n");
    }
}

void print_single_frame(const std::string& title, const Frame& frame) {
    const int n = static_cast<int>(frame.handles.size());
    fmt::print("{}\n{:<14} {:>11} {:>11} {:>11}\n", title, "", "x (m)", "y (m)", "speed (m/s)");
    for (int h : summary_handles(n)) {
        const Handle& hd = frame.handles[static_cast<size_t>(h)];
        fmt::print("{:<14} {:>11.6f} {:>11.6f} {:>11.6f}\n", handle_name(h, n), round6(hd.pos.x()),
                   round6(hd.pos.y()), round6(hd.speed));
    }
}

std::string format_resolved(double v, double resolution) {
    int decimals = 9;
    if (resolution > 0.0 && std::isfinite(resolution))
        // A resolution a hair over a power of ten (1.0000001e-10 from a bracket's rounding) counts
        // as it. Nine decimals at most (1e-9 s, the contest's precision): the searches resolve
        // 1e-11 m of head travel, which is finer than that for any head speed over 1 cm/s.
        decimals = std::clamp(static_cast<int>(std::floor(-std::log10(resolution) + 0.01)) - 1, 0, 9);
    return fmt::format("{:.{}f}", v, decimals);
}

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

std::string format_amount(double v, int decimals) {
    // Fixed decimals while they show at least half their digits of v and v has at most 9 digits
    // before the point; else as many significant digits as the fixed form shows at 1.
    const double a = std::abs(v);
    if (!std::isfinite(v) || a == 0.0 || (a >= std::pow(10.0, -decimals / 2) && a < 1e9))
        return fmt::format("{:.{}f}", v, decimals);
    return fmt::format("{:.{}e}", v, decimals);
}

void print_json(const Json& answer) { fmt::print("{}\n", json_text(answer)); }

Json jam_json(const std::optional<Jam>& j) {
    if (!j) return nullptr;
    return Json{{"time", j->time},
                {"travel", j->travel},
                {"handle", j->handle},
                {"kind", to_string(j->kind)},
                {"ahead", j->ahead},
                {"point", {j->point.x(), j->point.y()}},
                {"tolerance", j->tolerance}};
}

std::string jam_sentence(const Jam& j) {
    return fmt::format("the dragon can follow its path only {} t = {} s, where {}", j.ahead ? "until" : "from",
                       format_resolved(j.time, j.tolerance), describe(j));
}

std::string window_cuts(const Searched& w, const std::string& what) {
    std::string out;
    if (w.before) out += fmt::format("  {} starts there: {}\n", what, jam_sentence(*w.before));
    if (w.after) out += fmt::format("  {} ends there: {}\n", what, jam_sentence(*w.after));
    return out;
}

void add_window(Json& answer, const Searched& w) {
    answer["from"] = w.from;
    answer["to"] = w.to;
    answer["from_travel"] = w.from_travel;
    answer["to_travel"] = w.to_travel;
}

int checked_digits(const std::optional<int>& digits) {
    const int d = digits.value_or(kDefaultDigits);
    if (d < 0 || d > kMaxDigits)
        throw InputError(fmt::format("--digits {} is not allowed: use 0 to {} decimals", d, kMaxDigits));
    return d;
}

}  // namespace dragon::cli
