// The separating-axis test on oriented rectangles, in closed form (no corner lists).
#pragma once

#include <cmath>

#include "dragon/geometry.hpp"

namespace dragon {

// Half-extent of rectangle r projected on unit axis n.
inline double projected_radius(const Rect& r, const Vec2& n) {
    return r.half_length * std::abs(dot(r.axis, n)) + r.half_width * std::abs(cross(r.axis, n));
}

// The gap between the projections of a and b (centres d = cb - ca apart) on unit axis n.
inline double gap_on_axis(const Rect& a, const Rect& b, const Vec2& d, const Vec2& n) {
    return std::abs(dot(d, n)) - projected_radius(a, n) - projected_radius(b, n);
}

// On each candidate axis n the projections are intervals centred at c.n with the radii above;
// their gap is |(cb - ca).n| - ra(n) - rb(n). The largest gap over the four edge normals is > 0
// exactly when the rectangles are disjoint, is a lower bound on their distance, and when <= 0 is
// minus the penetration depth. (A NaN gap never wins: g > best is false.)
inline double projected_gap(const Rect& a, const Rect& b) {
    const Vec2 d = b.centre - a.centre;
    // A select, not a branch: the broad phase's pairs come in no order, so which axis wins is
    // unpredictable, and this is the clearance pass's inner loop. The axes are passed one by one:
    // copying them into an array first costs that loop about a third more time.
    const auto larger = [](double best, double g) { return g > best ? g : best; };
    double best = larger(-INFINITY, gap_on_axis(a, b, d, a.axis));
    best = larger(best, gap_on_axis(a, b, d, perp(a.axis)));
    best = larger(best, gap_on_axis(a, b, d, b.axis));
    return larger(best, gap_on_axis(a, b, d, perp(b.axis)));
}

struct SatGap {
    double gap;                // projected_gap(a, b)
    Vec2 axis = Vec2::Zero();  // the normal it is taken on, pointing from a towards b
};
inline SatGap sat_gap(const Rect& a, const Rect& b) {
    const Vec2 d = b.centre - a.centre;
    const Vec2 axes[4] = {a.axis, perp(a.axis), b.axis, perp(b.axis)};
    SatGap best{-INFINITY, Vec2::UnitX()};  // stays if every gap is NaN
    for (const Vec2& n : axes)
        if (const double g = gap_on_axis(a, b, d, n); g > best.gap) best = {g, dot(d, n) >= 0.0 ? n : Vec2(-n)};
    return best;
}

}  // namespace dragon
