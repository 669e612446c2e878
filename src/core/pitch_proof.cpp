// The minimum pitch's intervals proved pitch by pitch, feasible and colliding (the method is in
// pitch_proof.hpp).
#include "pitch_proof.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <utility>

#include "chain_front.hpp"
#include "golden_section.hpp"
#include "swept_proof.hpp"
#include "dragon/chain.hpp"
#include "dragon/collision.hpp"
#include "dragon/constants.hpp"
#include "dragon/path.hpp"
#include "dragon/portable_math.hpp"

namespace dragon {

namespace {

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
// Head radii between the first contact and the boundary at which a witness of a collision is
// looked for (the deepest overlap of the contact's pair).
constexpr int kWitnessSamples = 48;
// m: a witness whose pair still overlaps at a narrower range's middle pitch is looked for again
// this far either side of its radius (a grazing overlap's deepest place moves little with the
// pitch).
constexpr double kRefineRadius = 5e-3;
// Head radii from the boundary out to the start at which the whole chain is looked at for a
// witness before a run is made.
constexpr int kScanRadii = 12;
// m: the golden section on the deepest overlap stops at this bracket of head radius.
constexpr double kWitnessRadius = 1e-7;
// m: a colliding range is halved down to this, a 32nd of the search's resolution of a cut
// (tol::pitch), so that the colliding side is proved to within that resolution of the cut: a
// shallow overlap proves a range only some 3.5 times narrower than its distance from the cut
// (the contest's pair), and each level of halving towards the cut costs a few refined
// witnesses, no run. Ranges inside the resolution itself are not halved (prove_colliding).
constexpr double kCollidingFinest = tol::pitch / 32;
// Ranges of pitches one march or one colliding proof takes (each of prove_pitches' parts) before
// it leaves the rest unproved: halving runs out only at the finest widths above, so a part
// holding a wide stretch its proof cannot cover (a window of collision the search missed,
// inside a range claimed feasible) would take that width over the finest width in ranges, and
// minutes. The contest's parts take at most 207 (the colliding one next to the cut); a window
// of collision a micrometre wide claimed feasible about 2600 (PitchProof's tests), 3 s.
constexpr int kMaxRangesPerPart = 10000;
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

// Whether the cell's bounds hold (pitch_proof.hpp) in theta_b, the chain with the largest spans
// and least radii: every link keeps them (contact::link_keeps_cell_bounds).
bool bounds_hold(const std::vector<double>& theta_b, double b_lo, double b_hi) {
    for (size_t m = 0; m + 1 < theta_b.size(); ++m)
        if (!contact::link_keeps_cell_bounds(theta_b[m], theta_b[m + 1], b_lo, b_hi)) return false;
    return true;
}

// A range of pitches (m) whose cells are proved from head radius `from` (m) in.
struct Range {
    double p_lo, p_hi, from;
};

// Marches the range [p_lo, p_hi] of pitches from its start in to `boundary` (the turning
// space's radius), halving what its cells cannot prove; adds what it proved to `out`.
void march(const BenchSpec& spec, double start_turn, double boundary, double p_lo, double p_hi, PitchProof& out) {
    // The chains at the cell's four corners: its outer radius's (kept from the cell before, whose
    // inner radius it was) and its inner radius's, each at the range's two pitches.
    Frame outer_lo, outer_hi, inner_lo, inner_hi;
    double outer_r = NAN;  // m: the head radius of outer_lo and outer_hi (NAN: none yet)
    std::vector<double> theta_a, theta_b;
    contact::SweptWorkspace ws;
    std::vector<Range> todo{{p_lo, p_hi, Spiral(p_hi).b() * kTwoPi * start_turn}};
    for (int taken = 0; !todo.empty(); ++taken) {
        const Range range = todo.back();
        todo.pop_back();
        if (taken == kMaxRangesPerPart) {  // over budget: this range and those waiting are not proved
            out.unproved.push_back({range.p_lo, range.p_hi, true});
            for (const Range& r : todo) out.unproved.push_back({r.p_lo, r.p_hi, true});
            break;
        }
        ++out.pitch_ranges;
        // b as the spirals of the range's two ends have it (Spiral::b(): pitch / 2 pi).
        const double b_lo = Spiral(range.p_lo).b(), b_hi = Spiral(range.p_hi).b();
        outer_r = NAN;  // another range's pitches
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
                outer_r = NAN;  // the benches held may have changed
            }
            if (!(outer_r == r)) {
                front_at(spec, r, range.p_lo, watched, outer_lo);
                front_at(spec, r, range.p_hi, watched, outer_hi);
                outer_r = r;
            }
            front_at(spec, r_lo, range.p_lo, watched, inner_lo);
            front_at(spec, r_lo, range.p_hi, watched, inner_hi);
            // The second order in the head's radius first (its looseness falls with the cell's
            // square: it reaches a grazing pass in far fewer cells), then the first order (long
            // cells between benches far apart).
            contact::StepProof p = contact::prove_spiral_cell_second_order(
                spec, {inner_lo, inner_hi, outer_lo, outer_hi, r_lo, r, b_lo, b_hi}, ws);
            if (p.verdict != contact::StepVerdict::proved) {
                const std::array<contact::SpiralCorner, 4> corners{{{r_lo / b_lo, b_lo}, {r_lo / b_hi, b_hi},
                                                                     {r / b_lo, b_lo}, {r / b_hi, b_hi}}};
                p = contact::prove_spiral_cell(spec, outer_hi, inner_lo, corners, ws);
            }
            if (p.verdict == contact::StepVerdict::proved) {
                ++out.cells;
                out.least_gap = std::min(out.least_gap, p.least_gap);
                r = r_lo;
                std::swap(outer_lo, inner_lo);
                std::swap(outer_hi, inner_hi);
                outer_r = r;
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

// A corner of one bench inside another at head radius r: the witness of a collision.
struct Witness {
    double r = 0.0, depth = -INFINITY;  // m: the head radius; how deep the corner lies inside
    size_t inner = 0, outer = 0;        // the bench whose corner it is, and the bench it is inside (0-based)
    double along = 0.0, across = 0.0;   // which corner: +-1 each
    bool from_run = false;              // its pair is a run's first contact's
};

// The corner of benches a and b (0-based) deepest inside the other in the chain `f` (solved with
// the head at radius r): its distance to the other's boundary (negative when outside).
Witness deepest_corner(const Frame& f, double r, size_t a, size_t b) {
    Witness w;
    w.r = r;
    for (const auto& [inner, outer] : {std::pair{a, b}, std::pair{b, a}}) {
        const Rect& in = f.benches[inner];
        const Rect& out = f.benches[outer];
        for (const double along : {-1.0, 1.0})
            for (const double across : {-1.0, 1.0}) {
                const Vec2 c = in.centre + along * in.half_length * in.axis + across * in.half_width * perp(in.axis);
                const Vec2 d = c - out.centre;
                const double depth = std::min(out.half_length - std::abs(dot(d, out.axis)),
                                              out.half_width - std::abs(dot(d, perp(out.axis))));
                if (depth > w.depth) w = {r, depth, inner, outer, along, across};
            }
    }
    return w;
}

// The deepest corner of the pair (a, b) at head radius r for the spiral `mid`.
Witness pair_at(const BenchSpec& spec, const Spiral& mid, double r, size_t a, size_t b, Frame& f) {
    solve_chain_front(mid, spec, mid.arc({0, r / mid.b()}), 1.0, static_cast<int>(std::max(a, b)) + 2, f);
    return deepest_corner(f, r, a, b);
}

// The deepest overlap of the pair (a, b) for the spiral `mid` between head radii lo and hi
// (samples, then a golden section around the deepest: a grazing overlap lasts a few millimetres
// of radius, between samples).
Witness deepest_between(const BenchSpec& spec, const Spiral& mid, double lo, double hi, size_t a, size_t b, Frame& f) {
    const double spacing = (hi - lo) / kWitnessSamples;
    Witness best = pair_at(spec, mid, hi, a, b, f);
    for (int k = 1; k <= kWitnessSamples; ++k) {
        const Witness w = pair_at(spec, mid, hi - spacing * k, a, b, f);
        if (w.depth > best.depth) best = w;
    }
    if (spacing > 0.0) {
        const double g_lo = std::max(lo, best.r - spacing), g_hi = std::min(hi, best.r + spacing);
        const double r_peak =
            golden_min([&](double r) { return -pair_at(spec, mid, r, a, b, f).depth; }, g_lo, g_hi, kWitnessRadius).first;
        if (const Witness w = pair_at(spec, mid, r_peak, a, b, f); w.depth > best.depth) best = w;
    }
    return best;
}

// The head's radius at the start of the run at pitch p (m).
double start_radius(const Scenario& s, double p) { return Spiral(p).b() * kTwoPi * s.path.start_turn; }

// A witness for the pitch p without a run: the pairs overlapping most (by their separation) in
// the whole chain at a few head radii from the boundary out to `r_max` (at most p's start), the
// deepest of their corners refined by deepest_between. Deep collisions last long: most pitches
// of a colliding range show one at these radii; a grazing one is left to witness_from_run.
std::optional<Witness> witness_from_scan(const Scenario& s, double p, double r_max, Frame& f) {
    const Spiral mid(p);
    const double boundary = s.path.turn_radius;
    std::optional<Witness> best;
    for (int k = 0; k < kScanRadii; ++k) {
        const double r = boundary + (r_max - boundary) * k / kScanRadii;
        solve_chain_front(mid, s.bench, mid.arc({0, r / mid.b()}), 1.0, s.bench.handle_count(), f);
        const Clearance c = clearance(f);
        if (!(c.distance < 0.0)) continue;
        const Witness w = deepest_corner(f, r, static_cast<size_t>(c.bench_a - 1), static_cast<size_t>(c.bench_b - 1));
        if (!best || w.depth > best->depth) best = w;
    }
    if (!best) return std::nullopt;
    const double spacing = (r_max - boundary) / kScanRadii;
    const Witness w = deepest_between(s.bench, mid, std::max(boundary, best->r - spacing), std::min(r_max, best->r + spacing),
                                      std::min(best->inner, best->outer), std::max(best->inner, best->outer), f);
    return w.depth > best->depth ? w : *best;
}

// A witness for the pitch p from its run: its first contact's pair, at the radius (between the
// contact, or r_max if nearer the boundary, and the boundary) where that pair's deepest corner
// is deepest; `clear` says whether the run met neither a contact nor a jam, `jammed` whether its
// motion ended first.
std::optional<Witness> witness_from_run(const Scenario& s, double p, double r_max, Frame& f, bool& clear,
                                        bool& jammed) {
    const BoundaryRun run = run_to_boundary(s, p);
    clear = run.feasible();
    jammed = run.jam.has_value();
    if (!run.contact) return std::nullopt;  // a jam (or no contact at all): nothing to take a witness from
    const size_t a = static_cast<size_t>(run.contact->bench_a - 1), b = static_cast<size_t>(run.contact->bench_b - 1);
    Witness w = deepest_between(s.bench, Spiral(p), s.path.turn_radius, std::min(run.contact->head_radius, r_max), a, b, f);
    w.from_run = true;
    return w;
}

// Whether the witness's pair and radius prove a collision for every pitch of [p_lo, p_hi]
// (pitch_proof.hpp's second part): at its radius r, on every pitch's run (between the boundary
// and the start of p_lo's, the nearest in), the pair's deepest corner at the range's middle
// pitch lies inside the other bench deeper than the two benches can move as the pitch does.
// Fills `found` with that corner at the middle pitch.
bool witness_holds(const Scenario& s, double p_lo, double p_hi, const Witness& w, Witness& found, Frame& f,
                   std::vector<double>& theta_a, std::vector<double>& theta_b) {
    const BenchSpec& spec = s.bench;
    const double p_mid = 0.5 * (p_lo + p_hi);
    const Spiral mid(p_mid);
    const double r = w.r;
    if (!(r >= s.path.turn_radius) || !(r <= start_radius(s, p_lo))) return false;
    found = pair_at(spec, mid, r, std::min(w.inner, w.outer), std::max(w.inner, w.outer), f);
    if (!(found.depth > 0.0)) return false;
    // Every pitch of the range at that radius: each handle's polar offset D between its values at
    // the range's two ends (Proposition P2, the cell [r, start] x [b_lo, b_hi], its bounds checked
    // at (r, b_lo): this also proves the motion valid all the way down to r for every pitch).
    const double b_lo = Spiral(p_lo).b(), b_hi = Spiral(p_hi).b(), b_mid = mid.b();
    if (!angles_at(spec, r, p_hi, theta_a) || !angles_at(spec, r, p_lo, theta_b) || !bounds_hold(theta_b, b_lo, b_hi))
        return false;
    // How far handle i can be from its place at the middle pitch, in the frame turned with the
    // head (where the chain's shape is compared at each pitch: overlapping is the same turned):
    // P = (r + b D)(cos D, sin D) moves by D |b - b_mid| as b does and by at most
    // sqrt(b^2 + (r + b D)^2) |D - D_mid| as D does.
    const auto moved = [&](size_t i) {
        const double d_mid = f.handles[i].place.u - f.handles[0].place.u;
        const double d_lo = theta_a[i] - theta_a[0], d_hi = theta_b[i] - theta_b[0];
        const double spread = std::max(d_hi - d_mid, d_mid - d_lo);
        return d_hi * std::max(b_hi - b_mid, b_mid - b_lo) + math::hypot(b_hi, r + b_hi * d_hi) * spread;
    };
    // A corner c = cF F + cR R + j perp(F - R) of bench k moves by at most (|cF| + |j|) times its
    // front handle's move plus (|cR| + |j|) times its rear's.
    const auto corner_moved = [&](size_t k, double along, double across) {
        const Rect& rect = f.benches[k];
        const double d = spec.link_length(static_cast<int>(k) + 1);
        const double cF = 0.5 + along * rect.half_length / d, cR = 0.5 - along * rect.half_length / d;
        const double j = std::abs(across * rect.half_width / d);
        return (std::abs(cF) + j) * moved(k) + (std::abs(cR) + j) * moved(k + 1);
    };
    double outer_moved = 0.0;  // the outer bench moves no point farther than its farthest corner
    for (const double along : {-1.0, 1.0})
        for (const double across : {-1.0, 1.0}) outer_moved = std::max(outer_moved, corner_moved(found.outer, along, across));
    return found.depth > corner_moved(found.inner, found.along, found.across) + outer_moved + contact::kProofSlack;
}

// Proves the range [p_lo, p_hi] of an infeasible interval colliding, halving what one witness
// cannot cover; adds what it proved to `out`. Each range tries, in order of cost, its parent's
// witness (its pair and radius, at the range's own middle pitch), one from a scan of its middle
// pitch's chain, and one from its middle pitch's run. `cuts`: the infeasible interval's ends that
// the search found (a change of feasibility, resolved to tol::pitch; NaN for an end of the range
// searched). A range within tol::pitch of one is not halved: it may hold the feasible pitches
// the search's resolution leaves on this side of the cut, which a witness cannot cover, and
// halving it would run the dragon at every level.
void prove_colliding(const Scenario& s, double p_lo, double p_hi, std::pair<double, double> cuts,
                     PitchProof& out) {
    Frame f;
    std::vector<double> theta_a, theta_b;
    struct Todo {
        double lo, hi;
        std::optional<Witness> hint;  // the parent's deepest overlap
        bool near_clear = false;      // the parent's middle pitch ran clear to the boundary
    };
    std::vector<Todo> todo{{p_lo, p_hi, std::nullopt, false}};
    for (int taken = 0; !todo.empty(); ++taken) {
        const Todo range = todo.back();
        todo.pop_back();
        if (taken == kMaxRangesPerPart) {  // over budget: this range and those waiting are not proved
            out.unproved_colliding.push_back({range.lo, range.hi, false});
            for (const Todo& t : todo) out.unproved_colliding.push_back({t.lo, t.hi, false});
            break;
        }
        ++out.pitch_ranges;
        const double mid = 0.5 * (range.lo + range.hi);
        // m: a witness must lie on every pitch's run, so no farther out than the start of the
        // range's least pitch's (whose head starts nearest in).
        const double r_max = start_radius(s, range.lo);
        std::optional<Witness> seen;  // the deepest overlap seen at this range's middle pitch
        bool clear = false;           // its run met no contact and no jam
        bool jammed = false;          // its run's motion ended before any contact
        const auto holds = [&](const std::optional<Witness>& w) {
            if (!w) return false;
            Witness found;
            if (witness_holds(s, range.lo, range.hi, *w, found, f, theta_a, theta_b)) return true;
            found.from_run = w->from_run;
            if (found.depth > 0.0 && (!seen || found.depth > seen->depth)) seen = found;
            return false;
        };
        // Where the parent's pair still overlaps here, that pair again at the radius where it
        // overlaps most now (a grazing overlap's deepest place moves with the pitch).
        const auto refined = [&]() -> std::optional<Witness> {
            if (!seen) return std::nullopt;
            Witness w = deepest_between(s.bench, Spiral(mid), std::max(s.path.turn_radius, seen->r - kRefineRadius),
                                        std::min(r_max, seen->r + kRefineRadius), std::min(seen->inner, seen->outer),
                                        std::max(seen->inner, seen->outer), f);
            w.from_run = seen->from_run;
            return w;
        };
        // A run, the dearest, unless the deepest overlap seen is already a run's first contact's
        // pair (which a run here would find again: the ranges next to the cut).
        const auto from_run = [&]() -> std::optional<Witness> {
            if (seen && seen->from_run) return std::nullopt;
            return witness_from_run(s, mid, r_max, f, clear, jammed);
        };
        // The scan, unless the parent's middle pitch ran clear (a range claimed colliding that
        // holds feasible pitches: nothing overlaps near there, and the run decides).
        const auto from_scan = [&]() -> std::optional<Witness> {
            if ((seen && seen->from_run) || range.near_clear) return std::nullopt;
            return witness_from_scan(s, mid, r_max, f);
        };
        if (holds(range.hint) || holds(refined()) || holds(from_scan()) || holds(from_run())) {
            out.proved_colliding.push_back({range.lo, range.hi, false});
            continue;
        }
        ++out.subdivisions;
        // A middle pitch whose motion ends first gives no contact to take a witness from (nor,
        // as a rule, do the pitches around it): the range rests on the runs rather than being
        // halved across the width of the jams.
        // A middle pitch that runs clear, away from the cuts' resolution: a feasible pitch the
        // search missed (a window between its grid points); the range rests on the runs. Next
        // to a cut it is one the resolution left on this side, and the halves go on.
        const bool at_cut = range.lo >= cuts.second - tol::pitch || range.hi <= cuts.first + tol::pitch;
        const bool meets_cut = range.hi > cuts.second - tol::pitch || range.lo < cuts.first + tol::pitch;
        if (range.hi - range.lo <= kCollidingFinest || at_cut || jammed || (clear && !meets_cut)) {
            out.unproved_colliding.push_back({range.lo, range.hi, false});
            continue;
        }
        todo.push_back({mid, range.hi, seen, clear});
        todo.push_back({range.lo, mid, seen, clear});
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

PitchProof prove_pitches(const Scenario& s, const std::vector<PitchInterval>& intervals, Executor& ex) {
    // The ranges marched: each feasible interval in kFirstRanges equal parts.
    std::vector<std::pair<double, double>> ranges;
    for (const PitchInterval& iv : intervals) {
        if (!iv.feasible) continue;
        ranges.emplace_back(iv.lo, iv.lo);  // its least pitch alone, the search's answer
        for (int k = 0; k < kFirstRanges; ++k)
            ranges.emplace_back(k == 0 ? iv.lo : iv.lo + (iv.hi - iv.lo) * k / kFirstRanges,
                                k + 1 == kFirstRanges ? iv.hi : iv.lo + (iv.hi - iv.lo) * (k + 1) / kFirstRanges);
    }
    // And each infeasible interval's, to be proved colliding, with its ends that are cuts.
    const size_t feasible_ranges = ranges.size();
    std::vector<std::pair<double, double>> cuts(feasible_ranges, {NAN, NAN});
    for (const PitchInterval& iv : intervals) {
        if (iv.feasible) continue;
        const std::pair<double, double> ends{iv.lo > intervals.front().lo ? iv.lo : NAN,
                                             iv.hi < intervals.back().hi ? iv.hi : NAN};
        for (int k = 0; k < kFirstRanges; ++k) {
            ranges.emplace_back(k == 0 ? iv.lo : iv.lo + (iv.hi - iv.lo) * k / kFirstRanges,
                                k + 1 == kFirstRanges ? iv.hi : iv.lo + (iv.hi - iv.lo) * (k + 1) / kFirstRanges);
            cuts.push_back(ends);
        }
    }
    std::vector<PitchProof> parts(ranges.size());
    ex.parallel_for(ranges.size(), [&](size_t k, int) {
        if (k < feasible_ranges)
            march(s.bench, s.path.start_turn, s.path.turn_radius, ranges[k].first, ranges[k].second, parts[k]);
        else
            prove_colliding(s, ranges[k].first, ranges[k].second, cuts[k], parts[k]);
    });
    PitchProof out;
    for (const PitchProof& p : parts) {
        out.proved.insert(out.proved.end(), p.proved.begin(), p.proved.end());
        out.unproved.insert(out.unproved.end(), p.unproved.begin(), p.unproved.end());
        out.proved_colliding.insert(out.proved_colliding.end(), p.proved_colliding.begin(), p.proved_colliding.end());
        out.unproved_colliding.insert(out.unproved_colliding.end(), p.unproved_colliding.begin(),
                                      p.unproved_colliding.end());
        out.cells += p.cells;
        out.pitch_ranges += p.pitch_ranges;
        out.subdivisions += p.subdivisions;
        out.least_gap = std::min(out.least_gap, p.least_gap);
    }
    out.proved = merged(std::move(out.proved));
    out.unproved = merged(std::move(out.unproved));
    out.proved_colliding = merged(std::move(out.proved_colliding));
    out.unproved_colliding = merged(std::move(out.unproved_colliding));
    if (!out.proved.empty() && !intervals.empty()) {
        const double lo = intervals.front().lo;
        out.least_hi = out.proved.front().lo;
        out.least_lo = !out.proved_colliding.empty() && out.proved_colliding.front().lo == lo
                           ? std::min(out.proved_colliding.front().hi, out.least_hi)
                           : lo;
    }
    return out;
}

}  // namespace dragon
