// An upper bound on every handle's speed ratio over a whole stretch of head travel, from the
// chain at the stretch's two ends alone (docs/methods.md, section 10.1). Q5's maximum is
// enclosed by branch and bound on these.
//
// 1. Handles move forward (Lemma A). Each link's rear handle is a function F of its front
//    handle's arc position alone (the nearest root behind it). If, for every placing of the
//    front handle on its arc [s_i(x0), s_i(x1)] and the rear on [s_{i+1}(x0), s_{i+1}(x1)] a
//    link apart, both angles alpha (front tangent to the link) and beta (rear tangent to the
//    link) lie in (-pi/2, pi/2), then F' = cos alpha / cos beta > 0 wherever F takes values in
//    the rear arc, and F cannot leave that arc (it would have to come back with F' <= 0 at one
//    of its ends): every handle is non-decreasing and stays on its arc for the whole stretch.
//    Lemma A', for a handle that may stop or back up: while the rear stays in a candidate arc R
//    where cos beta > 0, |F'| <= G = max |cos alpha| / min cos beta; if F's start value give or
//    take G times the front's reach lies inside R, the rear never leaves R and stays within G
//    times the front's reaches of both its end places.
// 2. Angles over the stretch. alpha and beta differ from their values at x0 by at most the
//    turning of the path over the handle's arc plus the turning of the link, which is at most
//    2 asin((r_i + r_{i+1}) / 2d), r the handles' reaches (each end moves at most that far);
//    delta = alpha - beta by at most the two arcs' turnings. Enclosed by Taylor with remainder.
// 3. Slopes (interval arithmetic on the derivative of the rigid-link relation). With
//    g_i = cos alpha_i / cos beta_i, v_{i+1} = v_i g_i and kappa the path's signed curvature,
//    g_i' / g_i = v_i E_i, E_i = -kappa_i tan alpha_i + kappa_{i+1} g_i tan beta_i
//    + sin^2 delta_i / (d cos alpha_i cos^2 beta_i): while every handle so far moves forward the
//    slopes of log v add link by link; past one that may stop, v_{i+1}' = v_i' g_i + v_i^2 H_i,
//    H_i = g_i E_i (no cos alpha below the line). Derivatives in head travel x; |v_i'| <= L_i.
// 4. Each speed is Lipschitz (piecewise C1: its derivative jumps only where a handle crosses a
//    join, and the curvature's enclosure takes both sides), so on [x0, x1], h = x1 - x0:
//       max |v_i| <= (|v_i(x0) + v_i(x1)| + L_i h) / 2.
// 5. A calm tail (Lemma C). Where a handle moves forward over the whole stretch and ends it on a
//    spiral coiling in (Path::coil_in_spiral), every handle behind it stays on that spiral, at least
//    as far out. Each link there turns by less than pi/2 (a chord d <= 0.76 rho at radius >= rho
//    spans at most 2 asin(0.38) of polar angle, and the spiral turns by at most twice its polar
//    angle), and its rear end, where the curvature is the smaller, makes the smaller angle with
//    the link: beta <= alpha, so 0 < v_{i+1} = v_i cos alpha / cos beta <= v_i at every moment.
//    No handle behind it then outruns its bound, and the bound stops there (without `arcs`).
#pragma once

#include <vector>

#include "dragon/chain.hpp"
#include "dragon/path.hpp"
#include "dragon/scenario.hpp"

namespace dragon::speed {

// rad: angles of links with tangents must stay this far inside (-pi/2, pi/2) for Lemma A; far
// above the rounding of the computed angles (~1e-15 rad) and of Path::turning (~1e-15 rad).
inline constexpr double kAngleMargin = 1e-9;
// rad: added to every angle's enclosure: the computed handles are exact to ~1e-14 m
// (tol::newton_step) on links of at least ~1 m, so each computed angle is within ~1e-14 rad of
// the true one; 1e-12 is 100 times that.
inline constexpr double kAngleSlack = 1e-12;
// rad: the error of a link angle computed from the chain's handles (~1e-14 m each, on links of
// at least ~1 m) and tangents (a few ulps), taken 5 times over: a computed speed ratio v_i is
// then within kAngleError * sum_{k<i} (|tan alpha_k| + |tan beta_k|) plus 8 i ulps (relative)
// of the true one (each factor g = cos alpha / cos beta moves by |tan| times its angles' errors).
inline constexpr double kAngleError = 1e-13;

enum class BoundVerdict {
    bounded,       // every handle's speed ratio is bounded over the stretch
    not_monotone,  // a rear tangent may turn square to its link, or a link turn too far: a shorter stretch may be bounded
};

struct StretchBound {
    BoundVerdict verdict = BoundVerdict::bounded;
    // The largest speed ratio |v_i| / v_0 of any handle anywhere in the stretch is at most this
    // (the computed end speeds' errors included, by kAngleError's model), when bounded.
    double upper = 0.0;
    int handle = 0;  // the handle whose bound set `upper`
};

// The relative error of the computed speed ratios of `f`'s handles up to `handle`, by the model
// of kAngleError.
double ratio_error(const Frame& f, int handle);

// What a bound needs of one end of a stretch, gathered once per chain solved (a frame ends one
// stretch and begins the next).
struct ChainFacts {
    double head_arc = 0.0;       // m
    std::vector<Place> place;    // each handle's
    std::vector<double> kappa;   // the path's signed curvature at each handle, 1/m
    std::vector<double> speed;   // each handle's signed speed at head speed 1
    // Per link i (handles i and i + 1, u the unit link from rear to front): cos and sin of alpha
    // (from u to the front tangent) and of beta (from u to the rear tangent).
    std::vector<double> cos_a, sin_a, cos_b, sin_b;
};
// Gathers f's facts (f solved at head speed 1).
void gather(const Path& path, const Frame& f, ChainFacts& out);

// The bound over head travel between the chains c0 and c1 (c0 behind, both of the same chain on
// `path` at head speed 1, every moment between them within the valid motion).
//
// If `arcs` is given it receives, when bounded, where each handle lies over the whole stretch
// (Lemmas A and A'): on the path between the places lo and hi, whose arc turns by `turning`.
struct HandleArc {
    Place lo, hi;
    double turning = 0.0;  // rad
};
// c0 and c1 may hold the leading handles alone. Without `arcs` (chains solved up to a calm
// handle, Q5's scan) the bound then holds only if it stops at a calm tail among the handles both
// hold (Lemma C), and fails (not_monotone) otherwise; with `arcs` (a contact search's leading
// benches) it bounds the handles given.
StretchBound bound_stretch(const Path& path, const BenchSpec& spec, const ChainFacts& c0, const ChainFacts& c1,
                           std::vector<HandleArc>* arcs = nullptr);

// Lemma C's condition on handle j (0-based) of a chain of `spec` at `place`: the place on a
// spiral coiling in (Path::coil_in_spiral) at a radius of at least 1 / 0.76 times every link
// behind the handle. Over a stretch (with the handle moving forward all the way, ending it at
// `place`), or at one moment (with its speed above 0), no handle behind it moves faster.
bool calm_at(const Path& path, const BenchSpec& spec, const Place& place, size_t j);

// The first of f's handles that moves forward and is calm_at() its place: at that moment no
// handle behind it moves faster. f.handles.size() when none is (f may hold a leading part).
size_t first_calm_handle(const Path& path, const BenchSpec& spec, const Frame& f);

}  // namespace dragon::speed
