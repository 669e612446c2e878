// How close the benches come on the turnaround run, and whether they ever touch.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <fmt/format.h>

#include "core/golden_section.hpp"
#include "core/motion.hpp"
#include "dragon/analyses.hpp"
#include "dragon/collision.hpp"
#include "dragon/constants.hpp"
#include "dragon/turnaround.hpp"

namespace dragon {

namespace {

// Scan step as head travel, m (0.05 s at the contest's 1 m/s): where the benches are depends
// only on how far the head has come, so the scan must not coarsen with a faster head (nor crawl
// with a slower one). Between two samples the clearance can fall at most at the largest
// relative speed of two bench points, L <= 2 max point speed, so with clearances c_k, c_k+1 at
// the ends of a step its minimum over the step is at least (c_k + c_k+1 - L dt) / 2: a positive
// bound certifies the step collision-free.
constexpr double kScanTravel = 0.05;
// The scan's cost cap, in bench rectangles checked (samples times benches): ~20 s on one core.
// The contest's run takes 9e5; a head speed of 100 m/s over -100..100 s 9e7.
constexpr double kMaxBenchChecks = 1e8;
// The point-speed bound is taken at the samples; allow it to grow by this factor within a step.
constexpr double kSafety = tol::rate_safety;
// Pairs farther apart than this count as this far, m: only the smallest clearance matters, and
// the broad phase then looks at nearby pairs only.
constexpr double kCutoff = 0.5;
// Golden-section stop, s.
constexpr double kTimeTolerance = 1e-9;

double fastest_point(const Frame& f) {
    const std::vector<BenchMotion> motion = bench_motions(f);
    double fastest = 0.0;
    for (size_t k = 0; k < f.benches.size(); ++k)
        fastest = std::max(fastest, max_point_speed(f.benches[k], motion[k]));
    return fastest;
}

}  // namespace

RunClearance min_clearance(const Scenario& scenario, double t0, double t1, const WorkProgress& progress,
                           Executor* executor) {
    if (!std::isfinite(t0) || !std::isfinite(t1) || t1 <= t0)
        throw InputError("time range", fmt::format("{}..{} s", t0, t1), "it must be finite and non-empty");
    Scenario s = scenario;
    s.path.kind = PathKind::turnaround;
    const Simulation sim(s);
    Frame f;
    RunClearance out{};
    // Past the end of the valid motion the benches teleport: only the valid part is looked at.
    const Simulation::Span span = sim.clip_to_valid(t0, t1, "time range start", "time range end");
    out.from = t0 = span.from;
    out.to = t1 = span.to;
    out.jam = span.jam;
    auto probe = [&](double t) {
        ++out.evaluations;
        sim.frame_into(t, f);
        return clearance(f, kCutoff);
    };

    const double samples = std::ceil((t1 - t0) * s.head_speed / kScanTravel);
    if (!(samples * s.bench.bench_count <= kMaxBenchChecks))
        throw InputError("clearance time range", fmt::format("{}..{} s", t0, t1),
                         fmt::format("at head speed {} m/s it takes the head over {:.6g} m of the path, and the "
                                     "clearance scan would check {:.3g} chains of {} benches (at most {:.0e} bench "
                                     "checks); narrow it, or leave the clearance out", s.head_speed,
                                     (t1 - t0) * s.head_speed, samples, s.bench.bench_count, kMaxBenchChecks));
    const int steps = std::max(2, static_cast<int>(samples));
    const double dt = (t1 - t0) / steps;
    out.scan_step = dt;
    std::vector<double> c(static_cast<size_t>(steps) + 1), rate(c.size());
    for (int k = 0; k <= steps; ++k) {
        c[static_cast<size_t>(k)] = probe(k == steps ? t1 : t0 + k * dt).distance;  // t1 exactly: it may be a jam's
        rate[static_cast<size_t>(k)] = 2.0 * fastest_point(f);
        if (progress) progress(k + 1, steps + 1);
    }

    bool certified = true;
    for (size_t i = 0; i + 1 < c.size(); ++i) {
        const double l = kSafety * std::max(rate[i], rate[i + 1]);
        if (c[i] + c[i + 1] - l * dt <= 0.0) certified = false;
    }

    // Refine each local minimum of the samples that could dip below the best sample: within a
    // step of it the clearance falls at most about as fast as towards its neighbours.
    const double best_coarse = *std::min_element(c.begin(), c.end());
    out.distance = std::numeric_limits<double>::infinity();
    for (int k = 0; k <= steps; ++k) {
        const size_t i = static_cast<size_t>(k);
        const double left = k == 0 ? c[i] : c[i - 1], right = k == steps ? c[i] : c[i + 1];
        // A plateau counts once, at its first sample.
        if ((k > 0 && c[i] >= left) || c[i] > right || c[i] >= kCutoff) continue;
        if (c[i] - 2.0 * std::max(left - c[i], right - c[i]) > best_coarse) continue;
        const double a = t0 + std::max(0, k - 1) * dt, b = std::min(t1, t0 + std::min(steps, k + 1) * dt);
        const auto nearer = [](const Clearance& x, const Clearance& y) { return x.distance < y.distance; };
        const auto [at, best] = golden_min(probe, a, b, kTimeTolerance, nearer);
        if (best.distance < out.distance) {
            out.distance = best.distance;
            out.time = at;
            out.bench_a = best.bench_a;
            out.bench_b = best.bench_b;
        }
    }
    if (out.distance == std::numeric_limits<double>::infinity()) out.distance = kCutoff;
    // Not certified by the scan (benches come close, or touch): the exact search decides.
    ContactSearchOptions options;
    options.executor = executor;
    out.collision_free = certified || !first_contact(sim, t0, t1, options).has_value();
    return out;
}

}  // namespace dragon
