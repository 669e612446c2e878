#include "cli/report.hpp"

#include <algorithm>
#include <cmath>

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

void print_json(const Json& answer) {
    // NaN and infinities are written as null (nlohmann's choice too, made explicit).
    fmt::print("{}\n", answer.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace));
}

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

std::string json_number(double v) {
    if (!std::isfinite(v)) return "null";
    return fmt::format("{}", v);
}

std::string handles_json(const Frame& frame) {
    std::string out = "[";
    for (size_t i = 0; i < frame.handles.size(); ++i) {
        const Handle& h = frame.handles[i];
        out += fmt::format("{}{{\"x\": {:.6f}, \"y\": {:.6f}, \"speed\": {:.6f}}}", i ? ", " : "",
                           round6(h.pos.x()), round6(h.pos.y()), round6(h.speed));
    }
    return out + "]";
}

}  // namespace dragon::cli
