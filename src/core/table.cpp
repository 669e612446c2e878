// Tables of frames at evenly spaced times (the Q1 and Q4 tables).
#include <algorithm>
#include <cmath>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include <fmt/format.h>

#include "dragon/analyses.hpp"

namespace dragon {

void simulate_table_into(const Simulation& sim, double t0, double t1, double dt, std::vector<Frame>& frames) {
    if (!std::isfinite(dt) || dt <= 0.0)
        throw InputError(fmt::format("--step {} is not allowed: it must be a finite number > 0", dt));
    sim.require_valid(t0, "--from");
    sim.require_valid(t1, "--to");
    if (t1 < t0) throw InputError(fmt::format("--to {} is before --from {}: the time range is empty", t1, t0));
    // Count by index, so no drift. The last time is t1 when the grid lands on it up to rounding
    // (k dt within 1e-9 of the range, relative: 0.1 * 3 is not 0.3 in binary), else the last grid
    // time before it: --step 0.3 --to 1 ends at 0.9.
    const double span = (t1 - t0) / dt;
    const double slack = 1e-9 * std::max(span, 1.0);  // in steps
    const double count = std::floor(span + slack) + 1.0;
    const double rows = count * sim.scenario().bench.handle_count();
    if (rows > 5e6)
        throw InputError(fmt::format("--step {} gives {:.3g} frames x {} handles: at most 5,000,000 rows; "
                                     "use a larger step or a shorter range", dt, count,
                                     sim.scenario().bench.handle_count()));
    frames.resize(static_cast<size_t>(count));
    // Frames are independent: each core takes every n-th one (interleaved, so early and late
    // frames, which cost about the same, spread evenly). Small tables stay on this thread.
    const size_t workers = frames.size() < 64 ? 1 : std::max(1u, std::thread::hardware_concurrency());
    std::exception_ptr failure;
    std::mutex failure_lock;
    auto work = [&](size_t first) {
        try {
            for (size_t k = first; k < frames.size(); k += workers) {
                double t = t0 + static_cast<double>(k) * dt;
                if (t > t1 || (k + 1 == frames.size() && span - static_cast<double>(k) <= slack)) t = t1;
                sim.frame_into(t, frames[k]);
            }
        } catch (...) {
            const std::lock_guard<std::mutex> hold(failure_lock);
            if (!failure) failure = std::current_exception();
        }
    };
    std::vector<std::thread> pool;
    for (size_t w = 1; w < workers; ++w) pool.emplace_back(work, w);
    work(0);
    for (std::thread& th : pool) th.join();
    if (failure) std::rethrow_exception(failure);
}

std::vector<Frame> simulate_table(const Simulation& sim, double t0, double t1, double dt) {
    std::vector<Frame> frames;
    simulate_table_into(sim, t0, t1, dt, frames);
    return frames;
}

}  // namespace dragon
