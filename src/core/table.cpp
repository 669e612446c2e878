// Tables of frames at evenly spaced times (the Q1 and Q4 tables).
#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "dragon/analyses.hpp"
#include "dragon/executor.hpp"

namespace dragon {

void simulate_table_into(const Simulation& sim, double t0, double t1, double dt, std::vector<Frame>& frames,
                         Executor* executor) {
    if (!std::isfinite(dt) || dt <= 0.0)
        throw InputError(Key::step, error_value(dt), "it must be a finite number > 0");
    sim.require_valid(t0, Key::from);
    sim.require_valid(t1, Key::to);
    if (t1 < t0) throw InputError(Key::to, error_value(t1), fmt::format("it is before the start, {}", t0));
    // Count by index, so no drift. The last time is t1 when the grid lands on it up to rounding
    // (k dt within 1e-9 of the range, relative: 0.1 * 3 is not 0.3 in binary), else the last grid
    // time before it: --step 0.3 --to 1 ends at 0.9.
    const double span = (t1 - t0) / dt;
    const double slack = 1e-9 * std::max(span, 1.0);  // in steps
    const double count = std::floor(span + slack) + 1.0;
    const double rows = count * sim.scenario().bench.handle_count();
    if (rows > 5e6)
        throw InputError(Key::step, error_value(dt),
                         fmt::format("it gives {:.3g} frames x {} handles, and at most 5,000,000 rows fit; use a larger "
                                     "step or a shorter range", count, sim.scenario().bench.handle_count()));
    frames.resize(static_cast<size_t>(count));
    // Frames are independent: the executor's workers take them one at a time. Small tables
    // stay on this thread (starting the workers would cost more than the frames).
    InlineExecutor here(executor);
    Executor& ex = frames.size() < 64 ? here : executor_or(executor, here);
    ex.parallel_for(frames.size(), [&](size_t k, int) {
        double t = t0 + static_cast<double>(k) * dt;
        if (t > t1 || (k + 1 == frames.size() && span - static_cast<double>(k) <= slack)) t = t1;
        sim.frame_into(t, frames[k]);
    });
}

std::vector<Frame> simulate_table(const Simulation& sim, double t0, double t1, double dt, Executor* executor) {
    std::vector<Frame> frames;
    simulate_table_into(sim, t0, t1, dt, frames, executor);
    return frames;
}

void simulate_at(const Simulation& sim, const std::vector<double>& times,
                 const std::function<void(std::size_t, const Frame&)>& out, Executor* executor) {
    for (double t : times) sim.require_valid(t, Key::time);
    // Small sets stay on this thread (starting the workers would cost more than the frames).
    InlineExecutor here(executor);
    Executor& ex = times.size() < 64 ? here : executor_or(executor, here);
    std::vector<Frame> scratch(static_cast<std::size_t>(ex.workers()));
    ex.parallel_for(times.size(), [&](std::size_t k, int worker) {
        Frame& f = scratch[static_cast<std::size_t>(worker)];
        sim.frame_into(times[k], f);
        out(k, f);
    });
}

}  // namespace dragon
