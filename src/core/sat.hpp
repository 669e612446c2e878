// The separating-axis test on oriented rectangles, in closed form (no corner lists).
#pragma once

#include <cmath>

#include "dragon/geometry.hpp"

namespace dragon {

// Half-extent of rectangle r projected on unit axis n.
inline double projected_radius(const Rect& r, Vec2 n) {
    return r.half_length * std::abs(dot(r.axis, n)) + r.half_width * std::abs(cross(r.axis, n));
}

struct SatGap {
    double gap;  // largest projected gap over the four edge normals (> 0: apart)
    Vec2 axis;   // that normal, pointing from a towards b
};

// On each candidate axis n the projections are intervals centred at c.n with the radii above;
// their gap is |(cb - ca).n| - ra(n) - rb(n). The largest gap over the four edge normals is > 0
// exactly when the rectangles are disjoint, is a lower bound on their distance, and when <= 0 is
// minus the penetration depth.
inline SatGap sat_gap(const Rect& a, const Rect& b) {
    const Vec2 d = b.centre - a.centre;
    const Vec2 axes[4] = {a.axis, perp(a.axis), b.axis, perp(b.axis)};
    SatGap best{-INFINITY, {1, 0}};
    for (const Vec2 n : axes) {
        const double proj = dot(d, n);
        const double g = std::abs(proj) - projected_radius(a, n) - projected_radius(b, n);
        if (g > best.gap) best = {g, proj >= 0.0 ? n : -n};
    }
    return best;
}

}  // namespace dragon
