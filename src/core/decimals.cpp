#include "dragon/decimals.hpp"

#include <cmath>

#include <fmt/format.h>

namespace dragon {

double round6(double v) {
    const double r = std::round(v * 1e6) / 1e6;
    return r == 0.0 ? 0.0 : r;  // no "-0.000000"
}

std::string format_time(double t) {
    // Times come from t0 + k dt; print them without the binary noise (0.30000000000000004).
    const double r = std::round(t * 1e9) / 1e9;
    if (r == std::round(r) && std::abs(r) < 1e15) return fmt::format("{}", static_cast<long long>(r));
    return fmt::format("{}", r == 0.0 ? 0.0 : r);
}

}  // namespace dragon
