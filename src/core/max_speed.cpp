// Q5: the largest head speed that keeps every handle at or under a speed limit.
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "golden_section.hpp"
#include "make_path.hpp"
#include "chain_front.hpp"
#include "speed_bound.hpp"
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

// The coarse scan's cost cap, in handle positions solved (samples times handles): ~20 s on one
// core. The contest's run takes 9e5; a head speed of 100 m/s over the default -100..100 s
// (20 km of path) 9e7. Past the cap the scan would run for minutes or exhaust memory.
constexpr double kMaxHandlePositions = 1e8;

// The proof's stopping rule, relative: a stretch is done when its bound is within this of the
// largest ratio found. 1e-9 of the ratio is 1e-9 of the head speed, far inside the printed
// 6 decimals of m/s (1.2e-9 m/s at the contest's 1.25 m/s).
constexpr double kProofTolerance = 1e-9;
// m of head travel: stretches are not split below this (the chain's rounding, ~1e-14 m, is far
// below it); one still unbounded counts as unproved.
constexpr double kMinStretch = 1e-11;
// Stretches the proof may split before giving up (each split solves one chain): a cap that
// turns a bound that cannot close into an unproved answer instead of a hang.
constexpr int kMaxSubdivisions = 200000;
// The proof's first stretches are the scan's steps: the bound's excess over the true maximum
// grows as the square of a stretch's length (for the chain's tail, about 200 links times it);
// stretches of 4 to 32 steps where the scan's ratios lie below 0.8 to 0.97 of the maximum were
// tried, and cost 1.6 to 1.7 times the instructions (their bounds fail, and are split down to
// single steps anyway).
// Scan samples a worker takes at once (a chunk solves one chain more than its samples, for the
// bound of its last stretch: 2 % more with the proof).
constexpr int kScanChunk = 64;

// Handles past the first calm one (speed_bound.hpp's calm_at, Lemma C at one moment: none behind
// it moves faster) that the scan still solves, so that a stretch's bound finds the calm handle
// of its end in the chain at its start too (over a scan step of 1/32 of a link it moves back by
// one handle at most). A bound that does not (chains cut too short) fails, and the proof
// solves that stretch's chains whole.
constexpr int kCalmMargin = 4;

// The scan's chain at head arc s in f: solved up to its first calm handle and kCalmMargin more
// (the whole chain when it has none). `count`: the handles to try first (the last chain's cut),
// and then this one's.
void solve_to_calm(const Path& path, const BenchSpec& spec, double s, int& count, Frame& f) {
    const int n = spec.handle_count();
    for (;;) {
        solve_chain_front(path, spec, s, 1.0, std::min(count, n), f);
        const int held = static_cast<int>(f.handles.size());
        const int calm = static_cast<int>(speed::first_calm_handle(path, spec, f));
        const int want = calm < held ? std::min(n, calm + 1 + kCalmMargin) : n;
        count = want;
        if (want <= held) return;
    }
}

// A stretch's bound as the branch and bound keeps it: the bound, or NaN where a shorter
// stretch may be bounded.
double bound_value(const speed::StretchBound& b) { return b.verdict == speed::BoundVerdict::bounded ? b.upper : NAN; }

// The largest |speed| of a frame's handles (head speed 1) and the first handle reaching it.
SpeedRatio ratio_of(const Frame& f) {
    SpeedRatio best{std::abs(f.handles[0].speed), 0};
    for (size_t i = 1; i < f.handles.size(); ++i)
        if (std::abs(f.handles[i].speed) > best.ratio) best = {std::abs(f.handles[i].speed), static_cast<int>(i)};
    return best;
}

class RatioProbe {
public:
    RatioProbe(const Path& path, const BenchSpec& spec) : path_(path), spec_(spec) {}
    SpeedRatio operator()(double s) {
        ++evaluations;
        solve_chain(path_, spec_, s, 1.0, frame_);
        // Speeds are signed along the path (a handle may back up); the limit is on their size.
        return ratio_of(frame_);
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

MaxSpeed max_head_speed(const Scenario& scenario, double limit, const RunWindow& window, Executor* executor,
                        const MaxSpeedOptions& options) {
    InlineExecutor in_order(executor);
    Executor& ex = executor_or(executor, in_order);  // the scan's workers, and whether to stop
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
    if (!(options.samples_per_link > 0.0) || !std::isfinite(options.samples_per_link))
        throw std::invalid_argument("max_head_speed: samples_per_link must be finite and > 0");
    // The coarse scan's step, a fraction of the shortest link: at the default 32 samples per link
    // no handle moves more than ~1/32 of a link between samples (speed ratios stay near 1), so
    // every bump of the ratio, as wide as a handle's crossing of a link or a join, spans many.
    const double samples = std::ceil((s1 - s0) * options.samples_per_link / shortest);
    if (!(samples * s.bench.handle_count() <= kMaxHandlePositions))
        throw InputError(Key::time_range, fmt::format("{}..{} m of head travel", cut.from, cut.to),
                         fmt::format("the scan would solve {:.3g} chains of {} handles (at most {:.0e} handle "
                                     "positions); narrow it", samples, s.bench.handle_count(), kMaxHandlePositions));
    const int steps = std::max(2, static_cast<int>(samples));
    const double ds = (s1 - s0) / steps;

    // The scan, in chunks of kScanChunk samples spread over the executor's workers (each chunk
    // solves its own chains, and one more at its end for its last stretch's bound: every
    // sample's ratio, and every stretch's bound, is the same whichever worker made it).
    std::vector<double> rho(static_cast<size_t>(steps) + 1);
    // With the proof, each stretch between samples is bounded as the scan passes (the chain at
    // both its ends is at hand): upper[j] bounds the stretch from sample j to j + 1, NaN where no
    // bound holds.
    std::vector<double> upper(options.prove ? static_cast<size_t>(steps) : 0);
    const size_t chunks = static_cast<size_t>((steps + kScanChunk - 1) / kScanChunk);
    std::vector<int> chunk_evaluations(chunks, 0);
    ex.parallel_for(chunks, [&](size_t c, int) {
        const int k0 = static_cast<int>(c) * kScanChunk, k1 = std::min(steps, k0 + kScanChunk);
        Frame f;
        speed::ChainFacts facts[2];
        // Its samples k0 .. k1 - 1 (the last chunk also k1 = steps); k1 itself for the bound.
        const int last = options.prove || k1 == steps ? k1 : k1 - 1;
        // Each chain up to its calm tail (no handle behind moves faster: the ratio is the whole
        // chain's), the first of the chunk whole.
        int count = s.bench.handle_count();
        for (int k = k0; k <= last; ++k) {
            solve_to_calm(path, s.bench, k == steps ? s1 : s0 + k * ds, count, f);
            ++chunk_evaluations[c];
            if (k < k1 || k == steps) rho[static_cast<size_t>(k)] = ratio_of(f).ratio;
            if (!options.prove) continue;
            speed::gather(path, f, facts[k % 2]);
            if (k > k0)
                upper[static_cast<size_t>(k) - 1] = bound_value(speed::bound_stretch(path, s.bench, facts[(k + 1) % 2], facts[k % 2]));
        }
    });
    for (const int e : chunk_evaluations) probe.evaluations += e;

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
            check_stop(ex);
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
    double proof_hi = 0.0;  // the largest bound the proof accepted
    if (options.prove) {
        out.proof = MaxSpeedProof{};
        MaxSpeedProof& proof = *out.proof;
        proof.tolerance = kProofTolerance;
        // The bounds assume the valid motion over the window: proved here, step by step.
        find_jam(path, s.bench, sim.start_arc(), 1.0, cut.from, cut.to, &proof.motion, {true});
        proof.narrowest = ds;
        // A stretch [a, b] whose bound `top` (NaN: none) is not yet within the tolerance: split
        // it at its middle, the chain solved there counting as found, until each part's is.
        const auto done = [&](double top) { return top <= out.ratio * (1.0 + kProofTolerance); };
        const auto bound = [&](const speed::ChainFacts& c0, const speed::ChainFacts& c1) {
            return bound_value(speed::bound_stretch(path, s.bench, c0, c1));
        };
        const auto settle = [&](auto& self, const speed::ChainFacts& ca, const speed::ChainFacts& cb, double top) -> void {
            const double a = ca.head_arc, b = cb.head_arc;
            if (done(top)) {
                proof_hi = std::max(proof_hi, top);
                ++proof.stretches;
                proof.narrowest = std::min(proof.narrowest, b - a);
                return;
            }
            if (b - a < kMinStretch || proof.subdivisions >= kMaxSubdivisions) {
                ++proof.unproved;
                proof.unproved_travel += b - a;
                return;
            }
            if (proof.subdivisions % 256 == 0) check_stop(ex);
            ++proof.subdivisions;
            const double m = 0.5 * (a + b);
            Frame mid;
            solve_chain(path, s.bench, m, 1.0, mid);
            ++proof.evaluations;
            const SpeedRatio r = ratio_of(mid);
            if (r.ratio > out.ratio) {
                out.ratio = r.ratio;
                out.handle = r.handle;
                out.head_arc = m;
            }
            speed::ChainFacts cm;
            speed::gather(path, mid, cm);
            const double tl = bound(ca, cm), tr = bound(cm, cb);
            self(self, ca, cm, tl);
            self(self, cm, cb, tr);
        };
        Frame fa, fb;
        speed::ChainFacts ca, cb;
        for (size_t j = 0; j < upper.size(); ++j) {
            const double top = upper[j];
            if (done(top)) {
                proof_hi = std::max(proof_hi, top);
                ++proof.stretches;
                continue;
            }
            const int k = static_cast<int>(j);
            const double a = s0 + k * ds, b = k + 1 >= steps ? s1 : s0 + (k + 1) * ds;
            solve_chain(path, s.bench, a, 1.0, fa);
            solve_chain(path, s.bench, b, 1.0, fb);
            proof.evaluations += 2;
            speed::gather(path, fa, ca);
            speed::gather(path, fb, cb);
            settle(settle, ca, cb, top);
        }
        probe.evaluations += proof.evaluations;
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
    if (out.proof) {
        MaxSpeedProof& proof = *out.proof;
        proof.proved = proof.unproved == 0;
        proof.ratio_lo = out.ratio * (1.0 - speed::ratio_error(f, out.handle));
        // Each quotient rounded outward by an ulp.
        proof.max_head_speed_hi = std::nextafter(limit / proof.ratio_lo, INFINITY);
        if (proof.proved) {
            proof.ratio_hi = std::max(out.ratio, proof_hi);
            proof.max_head_speed_lo = std::nextafter(limit / proof.ratio_hi, 0.0);
        } else {
            proof.ratio_hi = std::numeric_limits<double>::infinity();
            proof.max_head_speed_lo = 0.0;
        }
    }
    out.evaluations = probe.evaluations;
    return out;
}

}  // namespace dragon
