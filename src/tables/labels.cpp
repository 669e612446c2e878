#include <cmath>
#include <string>

#include <fmt/format.h>

#include "dragon/tables.hpp"

namespace dragon {

std::string handle_label(int handle, int handle_count) {
    if (handle == 0) return "龙头";
    if (handle == handle_count - 1) return "龙尾（后）";
    if (handle == handle_count - 2) return "龙尾";
    return fmt::format("第{}节龙身", handle);
}

std::string format_time(double t, int digits) {
    std::string out = format_fixed(t, digits);
    if (out.find('.') != std::string::npos) {
        out.erase(out.find_last_not_of('0') + 1);  // 300.000000 -> 300., 0.100000 -> 0.1
        if (out.back() == '.') out.pop_back();
    }
    return out == "-0" ? "0" : out;
}

std::string time_header(double t) { return format_time(t) + " s"; }

void require_distinct_times(const std::vector<Frame>& frames, int digits, bool workbook) {
    const auto label = [&](double t, int d) { return workbook ? time_header(t) : format_time(t, d); };
    const auto distinct = [&](int d) {
        for (std::size_t k = 1; k < frames.size(); ++k)
            if (label(frames[k].time, d) == label(frames[k - 1].time, d)) return k;
        return std::size_t{0};
    };
    const std::size_t k = distinct(digits);
    if (k == 0) return;
    const double step = frames[k].time - frames[k - 1].time;
    const std::string same = label(frames[k].time, digits);
    if (workbook)
        throw InputError(Key::step, error_value(step),
                         fmt::format("a workbook labels its columns to 6 decimals of a second, and t = {} s and t = {} "
                                     "s would both read '{}': use a step of at least 1e-6 s, or a .csv or .json table",
                                     error_value(frames[k - 1].time), error_value(frames[k].time), same));
    int needed = digits + 1;
    while (needed <= kMaxDigits && distinct(needed) != 0) ++needed;
    throw InputError(Key::step, error_value(step),
                     needed <= kMaxDigits
                         ? fmt::format("the table prints times to {} decimals, and t = {} s and t = {} s would both "
                                       "read {}: print {} decimals or more, or use a coarser step",
                                       digits, error_value(frames[k - 1].time), error_value(frames[k].time), same, needed)
                         : fmt::format("no table tells t = {} s from t = {} s (at most {} decimals): use a coarser step",
                                       error_value(frames[k - 1].time), error_value(frames[k].time), kMaxDigits));
}

std::string format_fixed(double v, int digits) {
    // round6's rule while v * 10^digits is below 2^52 (where doubles still hold every integer):
    // 6 digits print what the workbooks hold.
    const double scale = std::pow(10.0, digits);  // exact up to 10^22
    double r = v;
    if (std::abs(v * scale) < 0x1p52) r = std::round(v * scale) / scale;
    std::string out = fmt::format("{:.{}f}", r, digits);
    if (out[0] == '-' && out.find_first_not_of("0.", 1) == std::string::npos) out.erase(0, 1);  // no "-0.00"
    return out;
}


}  // namespace dragon
