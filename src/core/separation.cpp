#include <algorithm>
#include <cmath>
#include <limits>

#include "sat.hpp"
#include "dragon/collision.hpp"

namespace dragon {

// Separating-axis test for two oriented rectangles. The candidate axes are the two edge normals
// of each rectangle; two convex polygons are disjoint iff some edge normal separates their
// projections, and when they overlap the smallest projected overlap over those normals is the
// penetration depth (the shortest translation that separates them). When they are apart the
// projected gap is only a lower bound on the distance, so the exact distance is taken as the
// smallest corner-to-rectangle distance (for disjoint convex polygons the closest pair always
// involves a corner of one of them).
Separation separation(const Rect& a, const Rect& b) {
    const SatGap sat = sat_gap(a, b);
    if (sat.gap > 0.0) {
        const Corners ca = corners(a), cb = corners(b);
        double dmin = INFINITY;
        Vec2 from = Vec2::Zero(), to = Vec2::Zero();
        for (int k = 0; k < 4; ++k) {
            const PointToRect pb = point_to_rect(ca.p[k], b);  // corner of a to b
            if (pb.distance < dmin) { dmin = pb.distance; from = ca.p[k]; to = pb.nearest; }
            const PointToRect pa = point_to_rect(cb.p[k], a);  // corner of b to a
            if (pa.distance < dmin) { dmin = pa.distance; from = pa.nearest; to = cb.p[k]; }
        }
        return {dmin, (to - from) / dmin, to};
    }
    // Overlapping: the witness is the corner that reaches deepest into the other rectangle along
    // the axis (a's corners push towards +axis into b, b's towards -axis into a); only corners
    // inside the other rectangle qualify. Two boards crossing like a plus sign have no corner
    // inside either: then the midpoint of their centres stands in.
    const Corners ca = corners(a), cb = corners(b);
    const double b_low = dot(b.centre, sat.axis) - projected_radius(b, sat.axis);
    const double a_high = dot(a.centre, sat.axis) + projected_radius(a, sat.axis);
    double depth = -INFINITY;
    Vec2 witness = 0.5 * (a.centre + b.centre);
    for (int k = 0; k < 4; ++k) {
        if (point_to_rect(ca.p[k], b).distance <= 0.0 && dot(ca.p[k], sat.axis) - b_low > depth) {
            depth = dot(ca.p[k], sat.axis) - b_low;
            witness = ca.p[k];
        }
        if (point_to_rect(cb.p[k], a).distance <= 0.0 && a_high - dot(cb.p[k], sat.axis) > depth) {
            depth = a_high - dot(cb.p[k], sat.axis);
            witness = cb.p[k];
        }
    }
    return {sat.gap, sat.axis, witness};
}

Vec2 contact_point(const Rect& a, const Rect& b) {
    Vec2 best = a.centre;
    double best_d = INFINITY;
    for (const Vec2& p : corners(a).p)
        if (const double d = point_to_rect(p, b).distance; d < best_d) best_d = d, best = p;
    for (const Vec2& p : corners(b).p)
        if (const double d = point_to_rect(p, a).distance; d < best_d) best_d = d, best = p;
    return best;
}

}  // namespace dragon
