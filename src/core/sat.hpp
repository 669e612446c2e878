// The separating-axis test on oriented rectangles, in closed form (no corner lists).
#pragma once

#include <cmath>

#include "dragon/geometry.hpp"

namespace dragon {

// Half-extent of rectangle r projected on unit axis n.
inline double projected_radius(const Rect& r, const Vec2& n) {
    return r.half_length * std::abs(dot(r.axis, n)) + r.half_width * std::abs(cross(r.axis, n));
}

struct SatGap {
    double gap;  // largest projected gap over the four edge normals (> 0: apart)
    Vec2 axis = Vec2::Zero();  // that normal, pointing from a towards b
};

// On each candidate axis n the projections are intervals centred at c.n with the radii above;
// their gap is |(cb - ca).n| - ra(n) - rb(n). The largest gap over the four edge normals is > 0
// exactly when the rectangles are disjoint, is a lower bound on their distance, and when <= 0 is
// minus the penetration depth.
inline SatGap sat_gap(const Rect& a, const Rect& b) {
    const Vec2 d = b.centre - a.centre;
    const Vec2 na = perp(a.axis), nb = perp(b.axis);
    // The winner is kept as an index and a sign, and its axis built once at the end: the loop
    // then works on doubles alone (callers that want only the gap pay for no vector copies).
    double best = -INFINITY;
    int winner = -1;
    bool towards_b = true;
    const auto consider = [&](int k, const Vec2& n) {
        const double proj = dot(d, n);
        const double g = std::abs(proj) - projected_radius(a, n) - projected_radius(b, n);
        if (g > best) best = g, winner = k, towards_b = proj >= 0.0;
    };
    consider(0, a.axis);
    consider(1, na);
    consider(2, b.axis);
    consider(3, nb);
    if (winner < 0) return {best, Vec2::UnitX()};  // every gap NaN: no axis wins
    const Vec2& n = winner == 0 ? a.axis : winner == 1 ? na : winner == 2 ? b.axis : nb;
    return {best, towards_b ? n : Vec2(-n)};
}

}  // namespace dragon
