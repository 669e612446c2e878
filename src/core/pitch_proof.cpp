// The minimum pitch's feasible intervals proved pitch by pitch (the method is in pitch_proof.hpp).
#include "pitch_proof.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <mutex>
#include <numbers>

#include "chain_front.hpp"
#include "swept_proof.hpp"
#include "dragon/chain.hpp"
#include "dragon/constants.hpp"
#include "dragon/errors.hpp"
#include "dragon/path.hpp"
#include "dragon/portable_math.hpp"

namespace dragon {

namespace {

// rad: a link's polar span must stay below a quarter turn for the monotonicity of the cell's
// bounds (pitch_proof.hpp), by a margin far above the rounding of the chain's angles (~1e-14).
constexpr double kMaxSpan = 0.5 * std::numbers::pi - 1e-9;
// Each feasible interval is cut into this many ranges of pitches at first, marched on their own
// (in parallel); a range its cells cannot prove is halved.
constexpr int kFirstRanges = 8;
// The first step in head radius, as a fraction of the radius, and how a proved step grows.
constexpr double kFirstRadiusStep = 0.01;
constexpr double kStepGrowth = 1.5;
// A cell not proved is taken again with half the radius step while that step, relative to the
// head's radius, is at least this fraction of the range's relative width in pitch (the two
// widen the enclosures alike); below it the range of pitches is halved instead.
constexpr double kRadiusToPitch = 0.25;
// The benches left out of the cells (those their offsets from the spiral keep apart) are found
// for this many radius steps at once: their proof holds in every cell inside.
constexpr double kTailSteps = 8.0;
// m: a radius step below this is not tried (far below any cell's use; stops a range that
// cannot be proved from stepping without end).
constexpr double kFinestRadiusStep = 1e-12;

// Every handle's angle on the spiral of this pitch with the head at radius r0 (false: a handle
// off the spiral's one piece).
bool angles_at(const BenchSpec& spec, double r0, double pitch, std::vector<double>& theta) {
    const Spiral spiral(pitch);
    return solve_spiral_chain_angles(spiral, spec, spiral.arc({0, r0 / spiral.b()}), theta);
}

// The leading `benches` benches of the same chain (its handles' angles are theta's, bit for bit).
void front_at(const BenchSpec& spec, double r0, double pitch, size_t benches, Frame& f) {
    const Spiral spiral(pitch);
    solve_chain_front(spiral, spec, spiral.arc({0, r0 / spiral.b()}), 1.0, static_cast<int>(benches) + 1, f);
}

// Whether the cell's bounds hold (pitch_proof.hpp): in theta_b, the chain with the largest spans
// and least radii, every link spans at most kMaxSpan and its front's radius exceeds
// b_hi tan(alpha / 2).
bool bounds_hold(const std::vector<double>& theta_b, double b_lo, double b_hi) {
    for (size_t m = 0; m + 1 < theta_b.size(); ++m) {
        const double alpha = theta_b[m + 1] - theta_b[m];
        if (!(alpha > 0.0) || !(alpha < kMaxSpan)) return false;
        if (!(b_lo * theta_b[m] > b_hi * math::tan(0.5 * alpha))) return false;
    }
    return true;
}

// A range of pitches (m) whose cells are proved from head radius `from` (m) in.
struct Range {
    double p_lo, p_hi, from;
};

// Marches the range [p_lo, p_hi] of pitches from its start in to `boundary` (the turning
// space's radius), halving what its cells cannot prove; adds what it proved to `out`.
void march(const BenchSpec& spec, double start_turn, double boundary, double p_lo, double p_hi, PitchProof& out) {
    Frame fa, fb;
    std::vector<double> theta_a, theta_b;
    contact::SweptWorkspace ws;
    std::vector<Range> todo{{p_lo, p_hi, Spiral(p_hi).b() * kTwoPi * start_turn}};
    while (!todo.empty()) {
        const Range range = todo.back();
        todo.pop_back();
        ++out.pitch_ranges;
        // b as the spirals of the range's two ends have it (Spiral::b(): pitch / 2 pi).
        const double b_lo = Spiral(range.p_lo).b(), b_hi = Spiral(range.p_hi).b();
        double r = range.from;  // m: every cell from the start in to here is proved
        double step = kFirstRadiusStep * r;
        bool done = true;
        double tail_lo = INFINITY, tail_hi = -INFINITY;  // m: the radii the tail's proof covers
        size_t watched = 0;   // the leading benches the cells enclose
        while (r > boundary) {
            const double r_lo = std::max(boundary, r - step);
            if (!(r_lo >= tail_lo && r <= tail_hi)) {
                // The chains with the least polar offsets (the tail cell's largest radius and b)
                // and the largest (its least), every handle's angle: the bounds, every bench's
                // offsets and the benches to watch, proved over kTailSteps steps at once (they
                // hold in every cell inside).
                tail_hi = r;
                tail_lo = std::max(boundary, r - kTailSteps * step);
                if (!angles_at(spec, tail_hi, range.p_hi, theta_a) || !angles_at(spec, tail_lo, range.p_lo, theta_b) ||
                    !bounds_hold(theta_b, b_lo, b_hi)) {
                    out.unproved.push_back({range.p_lo, range.p_hi, true});
                    done = false;
                    break;
                }
                watched = contact::spiral_cell_benches(spec, theta_a, theta_b, b_lo, b_hi, ws);
            }
            front_at(spec, r, range.p_hi, watched, fa);
            front_at(spec, r_lo, range.p_lo, watched, fb);
            const std::array<contact::SpiralCorner, 4> corners{{{r_lo / b_lo, b_lo}, {r_lo / b_hi, b_hi},
                                                                 {r / b_lo, b_lo}, {r / b_hi, b_hi}}};
            const contact::StepProof p = contact::prove_spiral_cell(spec, fa, fb, corners, ws);
            if (p.verdict == contact::StepVerdict::proved) {
                ++out.cells;
                out.least_gap = std::min(out.least_gap, p.least_gap);
                r = r_lo;
                step *= kStepGrowth;
                continue;
            }
            ++out.subdivisions;
            const double radius_share = (r - r_lo) / r, pitch_share = (range.p_hi - range.p_lo) / range.p_hi;
            if (radius_share >= kRadiusToPitch * pitch_share && 0.5 * (r - r_lo) >= kFinestRadiusStep) {
                step = 0.5 * (r - r_lo);
                continue;
            }
            done = false;
            if (range.p_hi - range.p_lo <= kPitchProofFinest) {
                out.unproved.push_back({range.p_lo, range.p_hi, true});
                break;
            }
            // Both halves go on from here: everything farther out is proved for the whole range.
            const double p_mid = 0.5 * (range.p_lo + range.p_hi);
            todo.push_back({p_mid, range.p_hi, r});
            todo.push_back({range.p_lo, p_mid, r});
            break;
        }
        if (done) out.proved.push_back({range.p_lo, range.p_hi, true});
    }
}

// Sorted, with touching ranges merged.
std::vector<PitchInterval> merged(std::vector<PitchInterval> v) {
    std::sort(v.begin(), v.end(), [](const PitchInterval& a, const PitchInterval& b) { return a.lo < b.lo; });
    std::vector<PitchInterval> out;
    for (const PitchInterval& iv : v) {
        if (!out.empty() && iv.lo <= out.back().hi) out.back().hi = std::max(out.back().hi, iv.hi);
        else out.push_back(iv);
    }
    return out;
}

}  // namespace

PitchProof prove_feasible_pitches(const Scenario& s, const std::vector<PitchInterval>& intervals, Executor& ex) {
    // The ranges marched: each feasible interval in kFirstRanges equal parts.
    std::vector<std::pair<double, double>> ranges;
    for (const PitchInterval& iv : intervals) {
        if (!iv.feasible) continue;
        for (int k = 0; k < kFirstRanges; ++k)
            ranges.emplace_back(k == 0 ? iv.lo : iv.lo + (iv.hi - iv.lo) * k / kFirstRanges,
                                k + 1 == kFirstRanges ? iv.hi : iv.lo + (iv.hi - iv.lo) * (k + 1) / kFirstRanges);
    }
    std::vector<PitchProof> parts(ranges.size());
    ex.parallel_for(ranges.size(), [&](size_t k, int) {
        march(s.bench, s.path.start_turn, s.path.turn_radius, ranges[k].first, ranges[k].second, parts[k]);
    });
    PitchProof out;
    for (const PitchProof& p : parts) {
        out.proved.insert(out.proved.end(), p.proved.begin(), p.proved.end());
        out.unproved.insert(out.unproved.end(), p.unproved.begin(), p.unproved.end());
        out.cells += p.cells;
        out.pitch_ranges += p.pitch_ranges;
        out.subdivisions += p.subdivisions;
        out.least_gap = std::min(out.least_gap, p.least_gap);
    }
    out.proved = merged(std::move(out.proved));
    out.unproved = merged(std::move(out.unproved));
    return out;
}

}  // namespace dragon
