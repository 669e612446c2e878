// The sentence every command says about the end of the valid motion, and a time to the digits
// it is known to (dragon/chain.hpp).
#include <algorithm>
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "dragon/chain.hpp"

namespace dragon {

std::string format_resolved(double v, double resolution) {
    int decimals = 9;
    if (resolution > 0.0 && std::isfinite(resolution))
        // A resolution a hair over a power of ten (1.0000001e-10 from a bracket's rounding) counts
        // as it. Nine decimals at most (1e-9 s, the contest's precision): the searches resolve
        // 1e-11 m of head travel, which is finer than that for any head speed over 1 cm/s.
        decimals = std::clamp(static_cast<int>(std::floor(-std::log10(resolution) + 0.01)) - 1, 0, 9);
    return fmt::format("{:.{}f}", v, decimals);
}

std::string jam_sentence(const Jam& j) {
    return fmt::format("the dragon can follow its path only {} t = {} s, where {}", j.ahead ? "until" : "from",
                       format_resolved(j.time, j.tolerance), describe(j));
}

}  // namespace dragon
