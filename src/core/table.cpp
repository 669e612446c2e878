#include <cmath>

#include <fmt/format.h>

#include "dragon/analyses.hpp"

namespace dragon {

std::vector<Frame> simulate_table(const Simulation& sim, double t0, double t1, double dt) {
    if (!std::isfinite(dt) || dt <= 0.0)
        throw InputError(fmt::format("--step {} is not allowed: it must be a finite number > 0", dt));
    sim.require_on_path(t0, "--from");
    sim.require_on_path(t1, "--to");
    if (t1 < t0) throw InputError(fmt::format("--to {} is before --from {}: the time range is empty", t1, t0));
    // Count by index so the last time is exactly t1 when the step divides the range.
    const double span = (t1 - t0) / dt;
    const double count = std::floor(span + 1e-9) + 1.0;
    const double rows = count * sim.scenario().bench.handle_count();
    if (rows > 5e6)
        throw InputError(fmt::format("--step {} gives {:.0f} frames x {} handles: at most 5,000,000 rows; "
                                     "use a larger step or a shorter range", dt, count,
                                     sim.scenario().bench.handle_count()));
    std::vector<Frame> frames(static_cast<size_t>(count));
    for (size_t k = 0; k < frames.size(); ++k) {
        double t = t0 + static_cast<double>(k) * dt;
        if (t > t1) t = t1;
        sim.frame_into(t, frames[k]);
    }
    return frames;
}

}  // namespace dragon
