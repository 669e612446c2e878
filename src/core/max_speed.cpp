// Q5: the largest head speed that keeps every handle at or under a speed limit.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <fmt/format.h>

#include "golden_section.hpp"
#include "make_path.hpp"
#include "dragon/chain.hpp"
#include "dragon/turnaround.hpp"

namespace dragon {

namespace {

// Golden-section stop: bracket width in head arc position, m. The speed ratio's maxima are
// either smooth (the value is then flat to ~1e-18 at this width) or kinks where a handle crosses a
// join (the location is then found to this width).
constexpr double kArcTolerance = 1e-9;

// Handle speeds this close (relative) count as equal: rounding in the chain is ~1e-15.
constexpr double kTieTolerance = 1e-12;

// Coarse scan step over the shortest link: with 32 samples per link length no handle moves more
// than ~1/32 of a link (speed ratios stay near 1) between samples, so every bump of the ratio,
// whose width is set by the time a handle needs to cross a link or a join, spans many samples.
constexpr double kSamplesPerLink = 32.0;

// The coarse scan's cost cap, in handle positions solved (samples times handles): ~20 s on one
// core. The contest's run takes 9e5; a head speed of 100 m/s over the default -100..100 s
// (20 km of path) 9e7. Past the cap the scan would run for minutes or exhaust memory.
constexpr double kMaxHandlePositions = 1e8;

class RatioProbe {
public:
    RatioProbe(const Path& path, const BenchSpec& spec) : path_(path), spec_(spec) {}
    SpeedRatio operator()(double s) {
        ++evaluations;
        solve_chain(path_, spec_, s, 1.0, frame_);
        // Speeds are signed along the path (a handle may back up); the limit is on their size.
        SpeedRatio best{std::abs(frame_.handles[0].speed), 0};
        for (size_t i = 1; i < frame_.handles.size(); ++i)
            if (std::abs(frame_.handles[i].speed) > best.ratio) best = {std::abs(frame_.handles[i].speed), static_cast<int>(i)};
        return best;
    }
    int evaluations = 0;

private:
    const Path& path_;
    const BenchSpec& spec_;
    Frame frame_;
};

// The largest ratio on [a, b] (a unimodal bracket around a coarse maximum; kinks are fine).
std::pair<double, SpeedRatio> golden_max(RatioProbe& probe, double a, double b) {
    const auto larger = [](const SpeedRatio& x, const SpeedRatio& y) { return x.ratio > y.ratio; };
    return golden_min([&probe](double s) { return probe(s); }, a, b, kArcTolerance, larger);
}

}  // namespace

SpeedRatio speed_ratio_at(const Path& path, const BenchSpec& spec, double head_arc) {
    RatioProbe probe(path, spec);
    return probe(head_arc);
}

MaxSpeed max_head_speed(const Scenario& scenario, double limit, const RunWindow& window, const Executor* executor) {
    const InlineExecutor stop(executor);
    if (!std::isfinite(limit) || limit <= 0.0)
        throw InputError(Key::limit, error_value(limit), "it must be a finite speed > 0 m/s");
    Scenario s = scenario;
    s.path.kind = PathKind::turnaround;
    const Simulation sim(s);
    const Path& path = sim.path();
    RatioProbe probe(path, s.bench);
    MaxSpeed out{};
    // Only the valid motion counts: past its end the speeds are those of a teleporting dragon.
    const WindowCut cut = cut_window(sim, window);
    out.window = cut.searched(s.head_speed);
    out.jam = cut.after ? cut.after : cut.before;
    for (const std::optional<Jam>& end : {cut.after, cut.before}) {
        if (!end || !speed_unbounded_at(*end)) continue;
        // The rear handle's speed has no bound as its root vanishes: no head speed will do.
        out.jam = end;
        out.unbounded = true;
        out.ratio = std::numeric_limits<double>::infinity();
        out.max_head_speed = 0.0;
        out.handle = end->handle;
        out.tied = {end->handle};
        out.time = end->time;
        out.head_arc = end->head_arc;
        out.travel = end->travel;
        return out;
    }

    // Work in head arc position: the ratio depends on where the chain is, not how fast it goes.
    const double v = s.head_speed;
    const double s0 = sim.start_arc() + cut.from, s1 = sim.start_arc() + cut.to;
    double shortest = s.bench.link_length(1);
    if (s.bench.bench_count > 1) shortest = std::min(shortest, s.bench.link_length(2));
    const double samples = std::ceil((s1 - s0) * kSamplesPerLink / shortest);
    if (!(samples * s.bench.handle_count() <= kMaxHandlePositions))
        throw InputError(Key::time_range, fmt::format("{}..{} m of head travel", cut.from, cut.to),
                         fmt::format("the scan would solve {:.3g} chains of {} handles (at most {:.0e} handle "
                                     "positions); narrow it", samples, s.bench.handle_count(), kMaxHandlePositions));
    const int steps = std::max(2, static_cast<int>(samples));
    const double ds = (s1 - s0) / steps;

    std::vector<double> rho(static_cast<size_t>(steps) + 1);
    for (int k = 0; k <= steps; ++k) {
        if (k % 256 == 0) check_stop(stop);
        rho[static_cast<size_t>(k)] = probe(k == steps ? s1 : s0 + k * ds).ratio;
    }

    // Refine every coarse local maximum that could still beat the best sample: between samples
    // the ratio rises at most ~slope * ds, with the slope estimated from the scan and doubled.
    // Each refined peak then checks that estimate: one that rose higher above its samples than
    // `reach` allowed shows the ratio turning faster than the scan saw, and the reach grows to
    // twice the largest rise seen, taking in the candidates it now allows.
    double slope = 0.0, best_coarse = 0.0;
    for (int k = 0; k < steps; ++k)
        slope = std::max(slope, std::abs(rho[static_cast<size_t>(k) + 1] - rho[static_cast<size_t>(k)]) / ds);
    for (double r : rho) best_coarse = std::max(best_coarse, r);
    double reach = 2.0 * slope * ds;

    out.ratio = -1.0;
    out.scan_step = ds / v;
    out.scan_travel = ds;
    std::vector<bool> refined(static_cast<size_t>(steps) + 1, false);
    for (bool widened = true; widened;) {
        widened = false;
        for (int k = 0; k <= steps; ++k) {
            const size_t i = static_cast<size_t>(k);
            // A plateau (say the head fastest, ratio exactly 1) counts once, at its first sample.
            const bool up = k == 0 || rho[i] > rho[i - 1];
            const bool down = k == steps || rho[i] >= rho[i + 1];
            if (refined[i] || !up || !down || rho[i] + reach < best_coarse) continue;
            refined[i] = true;
            check_stop(stop);
            ++out.candidates;
            const double a = s0 + std::max(0, k - 1) * ds, b = std::min(s1, s0 + std::min(steps, k + 1) * ds);
            const auto [at, r] = golden_max(probe, a, b);
            if (r.ratio > out.ratio) {
                out.ratio = r.ratio;
                out.handle = r.handle;
                out.head_arc = at;
            }
            const double rise = r.ratio - rho[i];
            if (rise > reach) {
                reach = 2.0 * rise;
                widened = true;
            }
        }
    }
    // Handles on one arc all move at the same speed: report every one that ties, and the first.
    Frame f;
    solve_chain(path, s.bench, out.head_arc, 1.0, f);
    ++probe.evaluations;
    for (size_t i = 0; i < f.handles.size(); ++i)
        if (std::abs(f.handles[i].speed) >= out.ratio * (1.0 - kTieTolerance)) out.tied.push_back(static_cast<int>(i));
    out.handle = out.tied.front();
    out.travel = out.head_arc - sim.start_arc();
    out.time = out.travel / v;
    out.max_head_speed = limit / out.ratio;
    out.evaluations = probe.evaluations;
    return out;
}

}  // namespace dragon
