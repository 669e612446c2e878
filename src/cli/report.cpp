#include "report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>

#include <fmt/format.h>

#include "dragon/paper_tables.hpp"
#include "dragon/tables.hpp"

namespace dragon::cli {

std::vector<int> summary_handles(int handle_count) { return paper_handles(handle_count); }

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

std::string format_amount(double v, int decimals) {
    // Fixed decimals while they show at least half their digits of v and v has at most 9 digits
    // before the point; else as many significant digits as the fixed form shows at 1.
    const double a = std::abs(v);
    if (!std::isfinite(v) || a == 0.0 || (a >= std::pow(10.0, -decimals / 2) && a < 1e9))
        return fmt::format("{:.{}f}", v, decimals);
    return fmt::format("{:.{}e}", v, decimals);
}

void print_json(const Json& answer) { fmt::print("{}\n", json_text(answer)); }

std::string window_cuts(const Searched& w, const std::string& what) {
    std::string out;
    if (w.before) out += fmt::format("  {} starts there: {}\n", what, jam_sentence(*w.before));
    if (w.after) out += fmt::format("  {} ends there: {}\n", what, jam_sentence(*w.after));
    return out;
}

int checked_digits(const std::optional<int>& digits) {
    const int d = digits.value_or(kDefaultDigits);
    if (d < 0 || d > kMaxDigits)
        throw InputError(fmt::format("--digits {} is not allowed: use 0 to {} decimals", d, kMaxDigits));
    return d;
}

}  // namespace dragon::cli
