// A proof that no two non-adjacent benches touch at any moment of a step, from the chain at the
// step's two ends alone: no rate, no sampling inside the step (docs/methods.md, section 6).
//
// 1. Every handle moves forward along the path over the step (its arc position at the step's
//    end is no smaller than at its start), proved link by link from the head: while the path
//    between a link's rear handle at the start and its front handle at the end turns by less
//    than pi/2, both ends' tangents make an angle below pi/2 with the link, so the rigid-link
//    relation v_{i+1} = v_i (T_i . u) / (T_{i+1} . u) keeps the rear speed's sign; a continuity
//    argument carries it over the whole step. So handle i lies, for the whole step, on the arc
//    of the path between its two end places.
// 2. That arc, of length L turning by tau, lies within L min(tau, 2) / 4 of the chord between
//    its ends (for every unit n, P(s).n is at most its linear interpolation plus
//    L/4 times the oscillation of T.n, which is at most min(tau, 2)).
// 3. A bench's corners are linear in its two handles (c = cF F + cR R + j perp(F - R), the
//    coefficients fixed by the board), so over the step every corner lies in the parallelogram
//    of the four combinations of the handles' end positions, dilated; the bench lies in the
//    convex hull of its 16 such points, dilated by the largest radius.
// 4. Two such enclosures apart along any axis (by more than kProofSlack) prove the two benches
//    apart for the whole step.
// 5. Those enclosures are first order in the step. Second order: every corner lies, at each
//    moment, within h^2 / 8 max|c''| of the point of its chord the moment gives (handle_accel.hpp
//    bounds c'' in head travel), so along axes turning at a constant rate from one end's to the
//    other's, two benches are at least their lesser end gap apart less what that allows
//    (methods.md 6.1, Propositions 7-8). Tried first; the first order where it fails.
// 6. On the plain spiral a step is a cell of one pitch (pitch_proof.hpp): the chains of its
//    travels are those with the head at the radii between its ends'. Where the cell's bounds
//    hold, the second order in the frame turned with the head (prove_spiral_cell_second_order,
//    methods.md 6.1 Proposition 9, 8.1 P5-P6) proves it far more tightly than item 5 (its longest
//    proved steps near Q2's contact are about three times as long), and needs no handle to move
//    forward: there it is the only proof tried.
#pragma once

#include <array>
#include <optional>
#include <numbers>
#include <span>
#include <vector>

#include "gentle_link.hpp"
#include "dragon/chain.hpp"
#include "dragon/path.hpp"
#include "dragon/portable_math.hpp"
#include "dragon/scenario.hpp"
#include "speed_bound.hpp"
#include "untouched_tail.hpp"

namespace dragon::contact {

// m: two enclosures must be farther apart than this to prove their benches apart. It absorbs
// what the floating-point model leaves out: the chain solve's error in each handle (~1e-14 m,
// tol::newton_step), the rounding of the enclosures' own few operations on coordinates of ~10 m
// (a few ulps, ~1e-15 m each) and of the arc lengths and turnings in the dilations (relative
// ~1e-15 of a dilation far below 1 m): 1e-12 m is 30 times all of them together. It also sets
// how close to a contact the proof reaches: within about kProofSlack / (closing speed) of head
// travel.
inline constexpr double kProofSlack = 1e-12;
// rad: the largest turning of the path over a link's hull for which step 1 above holds (the
// valid motion's proof uses the same induction, gentle_link.hpp).
inline constexpr double kMaxLinkTurning = gentle::kMaxLinkTurning;
// m: margin of the enclosures' bounding boxes within which a pair's separation is looked at; a
// pair farther apart is proved apart by its boxes alone, and the least separation a proof
// reports is at most this.
inline constexpr double kProofBoxMargin = 0.05;

enum class StepVerdict {
    proved,        // no two non-adjacent benches touch anywhere in the step
    too_close,     // some pair's enclosures are not proved apart: a shorter step may prove it
    not_monotone,  // a link turns too much over the step (or a handle moved back): no proof by enclosures
};

struct StepProof {
    StepVerdict verdict = StepVerdict::proved;
    // m: the least separation proved between two non-adjacent benches over the step (a lower
    // bound on their distance at every moment of it; at most kProofBoxMargin, or the apart_by
    // asked for when larger), when proved.
    double least_gap = INFINITY;
    int bench_a = 0, bench_b = 0;  // the pair that set least_gap (or first failed), 1..N
    bool second_order = false;     // proved by the second-order enclosures (item 5 above)
};

// Scratch reused between proofs (one per search worker).
struct SweptWorkspace {
    struct Swept {
        std::array<Vec2, 16> v;   // the enclosure's hull points: the first `count`
        size_t count = 16;
        double radius = 0.0;      // m: the hull is dilated by this
        double x0, x1, y0, y1;    // its bounding box, dilated, m
    };
    struct Box {
        double x0, x1, y0, y1;  // a bench's bounding box over its enclosures, dilated, m
        double radius;          // m: the largest dilation of its enclosures
    };
    std::vector<Swept> benches;  // each bench's enclosure (two per bench on the spiral)
    std::vector<Box> boxes;
    // A handle's place over the step, as a chord and a dilation: it lies in seg(p0, p1) + D(dilation).
    struct HandleSpan {
        Vec2 p0 = Vec2::Zero(), p1 = Vec2::Zero();
        double dilation = 0.0;  // m
    };
    std::vector<HandleSpan> spans;
    std::vector<Vec2> directions;  // the spiral's unit directions at a bench's handles' angles
    std::vector<double> arc0, arc1, dilation;
    std::vector<double> accel;  // each handle's bound on |d^2 P / dx^2| over the step (second-order enclosures)
    std::vector<double> hull;   // each link's hull turning over the step, rad
    std::vector<double> own;    // each handle's own arc's turning over the step, rad
    std::vector<double> speed;  // each handle's bound on its speed per unit of head speed over the step
    std::vector<double> corner_accel, corner_speed;  // each bench's bounds over its corners: |c''|, |c'|
    std::vector<int> order;
    std::vector<int> active;
    std::vector<std::optional<BenchReach>> reach;  // each bench's offsets from the spiral (cells only)
    speed::ChainFacts facts0, facts1;   // the steps proved by speed bounds (the turnaround's tight arcs)
    std::vector<speed::HandleArc> arcs;
};

// Which enclosures prove a step (items 3, 5 and 6 above): the first order (long steps),
// the second order (short steps near a contact; on the spiral, in the frame turned with the head
// where the step is a cell of one pitch, second_order_turned, else in the fixed frame), or
// either, the second order tried first or the first (the same verdict: a search tries first the
// one that proved its last step, since a failed try costs about as much as a proof). Tests
// choose one to check each on its own: second_order is then the fixed frame's on the spiral too.
enum class Enclosures { either, either_first_order_first, first_order, second_order, second_order_turned };

// The enclosures a search tries first on the step after one `last` proved: the order that proved it.
inline Enclosures tried_first_after(const StepProof& last) {
    return last.second_order ? Enclosures::either : Enclosures::either_first_order_first;
}

// Proves (or fails to prove) that no two non-adjacent benches of the chain touch at any head
// travel between the frames f0 and f1 (f0 earlier, both of the same chain on `path`, the head
// moving forward from one to the other within the valid motion); with `apart_by` (m), that none
// comes within apart_by of another (a lower bound on the least clearance over the step).
StepProof prove_step(const Path& path, const BenchSpec& spec, const Frame& f0, const Frame& f1, SweptWorkspace& ws,
                     double apart_by = 0.0, Enclosures which = Enclosures::either);

// rad: a link's polar span must stay below a quarter turn for the monotonicity of a cell's
// bounds (pitch_proof.hpp), by a margin far above the rounding of the chain's angles (~1e-14).
inline constexpr double kMaxCellSpan = 0.5 * std::numbers::pi - 1e-9;

// Whether a link whose front handle is at angle theta_front (rad) on the plain spiral and rear
// handle at theta_rear, in the chain of a cell with the largest spans and the least radii (its
// least head radius and b), keeps the cell's bounds for b in [b_lo, b_hi] (m/rad): its span is
// positive and below kMaxCellSpan, and its front's radius at b_lo exceeds b_hi tan(span / 2).
inline bool link_keeps_cell_bounds(double theta_front, double theta_rear, double b_lo, double b_hi) {
    const double alpha = theta_rear - theta_front;
    return alpha > 0.0 && alpha < kMaxCellSpan && b_lo * theta_front > b_hi * math::tan(0.5 * alpha);
}

// A value of the plain spiral's parameters at which benches are enclosed: the head's angle T
// (rad) and the spiral's b (pitch / 2 pi, m/rad). A handle at polar offset D from the head lies
// at b (T + D) (cos D, sin D) in the frame turned by -T: for fixed D, linear in (b T, b), the
// head's radius and b.
struct SpiralCorner {
    double T, b;
};

// The number K of leading benches of a cell of head radii and pitches on the plain spiral (see
// prove_spiral_cell) outside of which no two non-adjacent benches can touch anywhere in the
// cell, proved by their offsets from the spiral (untouched_tail.hpp's bench_reach): every pair
// with a bench numbered above K stays apart. theta_a, theta_b: every handle's angle in the chains
// with the least and the largest polar offsets; b_lo, b_hi: the cell's range of b. Fills
// ws.reach, which prove_spiral_cell then reads for the same cell.
size_t spiral_cell_benches(const BenchSpec& spec, const std::vector<double>& theta_a, const std::vector<double>& theta_b,
                           double b_lo, double b_hi, SweptWorkspace& ws);

// Proves (or fails to prove) that no two non-adjacent benches touch anywhere in a cell of head
// radii and pitches on the plain spiral (pitch_proof.cpp says what the cell is and why these
// are its bounds): every handle's polar offset from the head and every link's polar span lie,
// everywhere in the cell, between their values in the chains fa (the least) and fb (the
// largest), and the cell's (head radius, b) lie in the convex hull of `corners`. A pair's
// projected gap on a fixed axis is then concave over the cell, so least at a corner. fa and fb
// may hold the leading benches alone (spiral_cell_benches, called first for the cell, proves
// the rest apart).
StepProof prove_spiral_cell(const BenchSpec& spec, const Frame& fa, const Frame& fb, std::span<const SpiralCorner> corners,
                            SweptWorkspace& ws);

// A cell of head radii [r_lo, r_hi] and b (pitch / 2 pi) in [b_lo, b_hi] on the plain spiral, by
// the chains at its four corners (each holding the same leading benches: spiral_cell_benches,
// called first for the cell, proves the rest apart). b_lo == b_hi is a range of one pitch: a
// step of that dragon's motion.
struct SpiralCell {
    const Frame& inner_lo;  // at (r_lo, b_lo)
    const Frame& inner_hi;  // at (r_lo, b_hi)
    const Frame& outer_lo;  // at (r_hi, b_lo)
    const Frame& outer_hi;  // at (r_hi, b_hi)
    double r_lo, r_hi, b_lo, b_hi;
};

// prove_spiral_cell's proof at second order in the head's radius (docs/methods.md 8.1,
// Proposition P6): at each of the two radii the benches are enclosed over the range of b as
// there, and between them each corner lies within h^2 / 8 max|c''| of its chord in the frame
// turned with the head (shape_rates.hpp bounds c'' there), so a pair is apart by its lesser end
// gap along axes turning between the ends, less that (as in prove_step's second order). Its
// looseness falls with the square of the radius step: right for the short steps near a grazing
// pass, where the first order needs steps as short as the gap.
StepProof prove_spiral_cell_second_order(const BenchSpec& spec, const SpiralCell& cell, SweptWorkspace& ws);

}  // namespace dragon::contact
