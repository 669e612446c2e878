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

std::string format_time(double t) {
    // Times come from t0 + k dt; print them without the binary noise (0.30000000000000004).
    const double r = std::round(t * 1e9) / 1e9;
    if (r == std::round(r) && std::abs(r) < 1e15) return fmt::format("{}", static_cast<long long>(r));
    return fmt::format("{}", r == 0.0 ? 0.0 : r);
}

std::string time_header(double t) { return format_time(t) + " s"; }

double round6(double v) {
    const double r = std::round(v * 1e6) / 1e6;
    return r == 0.0 ? 0.0 : r;  // no "-0.000000"
}

}  // namespace dragon
