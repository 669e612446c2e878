#include "contact_step.hpp"

#include <algorithm>
#include <cmath>

#include "contact_bounds.hpp"
#include "corner_gaps.hpp"
#include "sat.hpp"

namespace dragon::contact {

// One pass over the broad phase's pairs gives the clearance and the safe step.
//
// Steps are in m of head travel, speeds and rates per m of head travel (the search runs on the
// motion at 1 m/s). Each pair first gets the first-order step g / (ws.rate_safety L) from its
// projected gap g and the bound L on its closing speed. Pairs whose first-order step could decide the step are then
// looked at closer: their eight corner gaps, each with its exact rate, are bounded to second
// order, d(x + h) >= d + rate h - M h^2 / 2, with M ws.rate_safety times the larger of the rate
// changes seen since the last evaluation and a rotational floor. A pair's step is the better
// of the two bounds. This is what makes grazing passes cheap: a corner gliding past at a
// tiny distance with zero rate still allows sqrt(2 d / M), where the first-order bound would
// crawl. The curvature each step relied on is checked at the next evaluation; if the rates
// changed faster, the caller retreats and retries shorter.
// `memory` is what the last accepted evaluation saw; this one's goes to `next` (cleared first),
// for the caller to keep if it accepts the step.
namespace {

// Stage 1: every broad-phase pair's first-order step. Pairs their radii keep apart for the whole
// step, farther than a probe looks, are passed over (gap infinite); the others get their
// projected gap (a lower bound on the distance), and those whose first-order step could set the
// step go to ws.tight. Returns the index of the pair with the smallest projected gap. `step`
// (m of head travel) is how far this evaluation is from `last`, whose promises `check` holds it to.
size_t screen_pairs(const Frame& f, const std::vector<std::pair<int, int>>& pairs, double cap, const StepRecord& last,
                    StepRecord& next, bool check, double step, Workspace& ws, bool& broken) {
    const std::vector<BenchMotion>& motion = ws.motion;
    ws.tight.clear();
    ws.gaps.resize(pairs.size());
    next.gaps.clear();
    double best_gap = INFINITY;
    size_t seed = 0;
    for (size_t k = 0; k < pairs.size(); ++k) {
        const size_t i = static_cast<size_t>(pairs[k].first - 1), j = static_cast<size_t>(pairs[k].second - 1);
        const BenchMotion& ma = motion[i];
        const BenchMotion& mb = motion[j];
        // Relative velocity field of b seen from a: affine, so within a's rectangle its norm is
        // at most its value at a's centre plus the turn-rate difference times the half-diagonal
        // (plus b's turn rate times the gap between them, below).
        const double spread = norm(mb.at(ma.centre) - ma.v_centre) + std::abs(mb.omega - ma.omega) * ws.half_diagonals[i];
        const double radial_closing = ws.radial[i].speed + ws.radial[j].speed;
        const std::uint64_t key = key_of(pairs[k].first - 1, pairs[k].second - 1);
        // The step that led here promised this pair a gap for its whole length: does it hold at
        // the closing speeds measured here? (A pair the last evaluation had no record of was
        // beyond its broad phase's margin then: its group answers for it.)
        if (check) {
            if (const GapRecord* was = last.gaps.find(key)) {
                const double closing = spread + std::abs(mb.omega) * std::max(was->gap, 0.0);
                const bool held = was->second_order || (was->gap > 0.0 && closing * step <= was->gap * (1.0 + tol::promise_relative)) ||
                                  (was->radial_gap > 0.0 && radial_closing * step <= was->radial_gap * (1.0 + tol::promise_relative));
                if (!held) broken = true;
            }
        }
        // Benches on neighbouring turns slide past each other: when their radii alone keep them
        // apart for the whole step and farther than a probe would look, they cannot set the step,
        // touch, or be probed, and need no closer look (most pairs, away from the centre).
        const double radial_first_order = radial_step(ws.radial[i], ws.radial[j], ws.rate_safety);
        const double rgap = radial_gap(ws.radial[i], ws.radial[j]);
        if (radial_first_order >= cap && rgap >= kProbeGap) {
            ws.gaps[k] = INFINITY;
            next.gaps.emplace(key, {0.0, 0.0, rgap, radial_closing});
            continue;
        }
        const double g = projected_gap(f.benches[i], f.benches[j]);  // a lower bound on the distance
        ws.gaps[k] = g;
        if (g < best_gap) best_gap = g, seed = k;
        const double gap = std::max(g, 0.0);
        const double bound = spread + std::abs(mb.omega) * gap;
        next.gaps.emplace(key, {gap, bound, rgap, radial_closing});
        // First-order step gap / (ws.rate_safety bound), divided out only for the pairs that could set it.
        if (gap < cap * ws.rate_safety * bound) {
            const double first_order = std::max(gap / (ws.rate_safety * bound), radial_first_order);
            if (first_order < cap) ws.tight.push_back({first_order, bound, k});
        }
    }
    return seed;
}

// Stage 2: the pairs of ws.tight, smallest first-order step first (popped from a heap: usually
// only a part of the list is looked at before the first-order steps exceed the step found so
// far), each bounded to second order on its eight corner gaps. Returns the step; ws.pair_steps
// holds each pair looked at with its step, and `skipped` what every other pair allows at least.
double refine_pairs(const Frame& f, const std::vector<std::pair<int, int>>& pairs, double x, double cap,
                    const Memory& memory, Memory& next, FlatMap<GapRecord>& gaps, bool check, Workspace& ws,
                    double& skipped, bool& bound_broken) {
    using Candidate = Workspace::Candidate;
    std::vector<Candidate>& tight = ws.tight;
    const auto later = [](const Candidate& x, const Candidate& y) { return x.first_order > y.first_order; };
    std::make_heap(tight.begin(), tight.end(), later);
    next.clear();
    ws.pair_steps.clear();
    double step = cap;
    skipped = cap;
    while (!tight.empty()) {
        std::pop_heap(tight.begin(), tight.end(), later);
        const Candidate c = tight.back();
        tight.pop_back();
        if (c.first_order >= step) {  // this pair and the rest cannot lower the step
            skipped = std::min(skipped, c.first_order);
            break;
        }
        const int ia = pairs[c.k].first - 1, ib = pairs[c.k].second - 1;
        const BenchMotion& ma = ws.motion[static_cast<size_t>(ia)];
        const BenchMotion& mb = ws.motion[static_cast<size_t>(ib)];
        const auto gaps8 = corner_gaps(f.benches[static_cast<size_t>(ia)], ma, f.benches[static_cast<size_t>(ib)], mb);
        // Rotational floor: the corner-to-edge direction turns at most at |omega_a| + |omega_b|,
        // tilting a relative velocity of size <= bound.
        double observed = (std::abs(ma.omega) + std::abs(mb.omega)) * c.bound;
        const std::uint64_t key = key_of(ia, ib);
        PairMemory mem{x, {}, 0.0};
        if (const PairMemory* last = memory.find(key); last && last->travel != x) {
            const double dx = std::abs(x - last->travel);  // m of head travel since the rates were measured
            for (size_t q = 0; q < 8; ++q) {
                const double change = std::abs(gaps8[q].rate - last->rates[q]);
                observed = std::max(observed, change / dx);
                // The last step assumed the rates change by at most curvature * dx.
                if (check && change > last->curvature * dx * (1.0 + tol::promise_relative) + tol::promise_rate_change) bound_broken = true;
            }
        }
        mem.curvature = ws.rate_safety * observed;
        double h2 = INFINITY;
        for (size_t q = 0; q < 8; ++q) {
            mem.rates[q] = gaps8[q].rate;
            h2 = std::min(h2, second_order_step(gaps8[q].distance, gaps8[q].rate, mem.curvature));
        }
        next.emplace(key, mem);
        const double pair_step = std::max(c.first_order, h2);
        if (h2 > c.first_order)
            if (GapRecord* r = gaps.find(key)) r->second_order = true;
        ws.pair_steps.push_back({key, pair_step});
        step = std::min(step, pair_step);
    }
    return step;
}

// Stage 3: the closest pair, by exact distances only where the projected gap (a lower bound)
// could still win, and the rate at which its separation changes now.
void closest_pair(const Frame& f, const std::vector<std::pair<int, int>>& pairs, size_t seed, const Workspace& ws,
                  Approach& a) {
    auto exact = [&](size_t k) {
        const Separation s = separation(f.benches[static_cast<size_t>(pairs[k].first - 1)],
                                        f.benches[static_cast<size_t>(pairs[k].second - 1)]);
        if (s.distance < a.clear.distance) a.clear = {s.distance, pairs[k].first, pairs[k].second, s.axis, s.point};
    };
    if (ws.gaps[seed] < INFINITY) exact(seed);
    for (size_t k = 0; k < pairs.size(); ++k)
        if (k != seed && ws.gaps[k] < a.clear.distance) exact(k);
    if (a.clear.bench_a > 0 && a.clear.distance > 0.0) {
        // Separation rate of the closest pair: the witness on b moving away from a along the axis.
        const BenchMotion& ma = ws.motion[static_cast<size_t>(a.clear.bench_a - 1)];
        const BenchMotion& mb = ws.motion[static_cast<size_t>(a.clear.bench_b - 1)];
        const Vec2 q = a.clear.point;
        const Vec2 p = q - a.clear.distance * a.clear.axis;
        a.rate = dot(a.clear.axis, mb.at(q) - ma.at(p));
    }
}

}  // namespace

// The clearances (approach()'s closest pair, clearance()) are the least exact separation over
// the pairs they look at, each looked at unless its projected gap is already no smaller than
// the least so far, and separation() returns the projected gap itself whenever that is <= 0.
// So a pair with a projected gap <= 0 (the broad phase at any margin holds it) makes either
// clearance <= 0: yes. When every pair of the broad phase at margin kSureGap has a projected gap
// of at least kSureGap, every pair is truly at least that far apart (a pair beyond that margin
// is farther, as the broad phase never misses one), and no separation computed for it can round
// to 0: no. Between those, a separation can round to 0 where the projected gap is a rounding
// above it (8e-17 m in one of the map's runs), and whether a clearance sees it depends on the
// order it looks at its pairs in: unsure.
Overlap overlap_of(const Frame& f, Workspace& ws) {
    if (f.benches.size() < 3) return Overlap::no;
    Overlap out = Overlap::no;
    for (const auto& [a, b] : ws.broad.candidate_pairs(f, kSureGap)) {
        const double g = projected_gap(f.benches[static_cast<size_t>(a - 1)], f.benches[static_cast<size_t>(b - 1)]);
        if (g <= 0.0) return Overlap::yes;
        if (g < kSureGap) out = Overlap::unsure;
    }
    return out;
}

Approach approach(const Frame& f, double x, double max_step, const StepRecord& last, StepRecord& next, bool check,
                  Workspace& ws) {
    Approach a{{INFINITY, 0, 0, Vec2::Zero(), Vec2::Zero()}, INFINITY, 0.0, false, INFINITY};
    next.travel = x;
    if (f.benches.size() < 3) return a;
    const double step = std::abs(x - last.travel);  // m of head travel since the last accepted evaluation
    // The search's own scratch (a search evaluates hundreds of frames).
    bench_motions_into(f, ws.motion);
    ws.half_diagonals.resize(f.benches.size());
    for (size_t k = 0; k < f.benches.size(); ++k) ws.half_diagonals[k] = half_diagonal(f.benches[k]);
    radial_extents(f, ws.motion, ws.radial);
    // Pairs beyond the margin: bounded group by group (far_pairs_step).
    const double cap = std::min(max_step, far_pairs_step(f, ws.motion, ws.half_diagonals, ws.radial, kMargin,
                                                         next.groups, ws.rate_safety, check ? &last.groups : nullptr, step,
                                                         &a.bound_broken));
    const auto& pairs = ws.broad.candidate_pairs(f, kMargin);
    const size_t seed = screen_pairs(f, pairs, cap, last, next, check, step, ws, a.bound_broken);
    double skipped = cap;
    a.safe_step = refine_pairs(f, pairs, x, cap, last.near, next.near, next.gaps, check, ws, skipped, a.bound_broken);
    if (pairs.empty()) {
        a.clear = clearance(f, kMargin, ws.broad);
        a.others_step = a.safe_step;
        return a;
    }
    closest_pair(f, pairs, seed, ws, a);
    // No pair but the closest one can touch before others_step.
    const std::uint64_t closest = a.clear.bench_a > 0 ? key_of(std::min(a.clear.bench_a, a.clear.bench_b) - 1,
                                                                std::max(a.clear.bench_a, a.clear.bench_b) - 1)
                                                       : ~std::uint64_t{0};
    a.others_step = skipped;
    for (const auto& [key, pair_step] : ws.pair_steps)
        if (key != closest) a.others_step = std::min(a.others_step, pair_step);
    return a;
}

}  // namespace dragon::contact
