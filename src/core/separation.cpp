#include <algorithm>
#include <cmath>
#include <limits>

#include "core/sat.hpp"
#include "dragon/collision.hpp"

namespace dragon {

namespace {

// Distance from point p to rectangle r (0 inside), and the nearest point of r.
struct PointRect {
    double distance;
    Vec2 nearest;
};
PointRect point_to_rect(Vec2 p, const Rect& r) {
    const Vec2 n = perp(r.axis);
    const Vec2 w = p - r.centre;
    const double x = dot(w, r.axis), y = dot(w, n);
    const double cx = std::clamp(x, -r.half_length, r.half_length);
    const double cy = std::clamp(y, -r.half_width, r.half_width);
    return {std::sqrt((x - cx) * (x - cx) + (y - cy) * (y - cy)), r.centre + cx * r.axis + cy * n};
}

}  // namespace

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
        Vec2 from{}, to{};
        for (int k = 0; k < 4; ++k) {
            const PointRect pb = point_to_rect(ca.p[k], b);  // corner of a to b
            if (pb.distance < dmin) { dmin = pb.distance; from = ca.p[k]; to = pb.nearest; }
            const PointRect pa = point_to_rect(cb.p[k], a);  // corner of b to a
            if (pa.distance < dmin) { dmin = pa.distance; from = pa.nearest; to = cb.p[k]; }
        }
        return {dmin, (to - from) / dmin, to};
    }
    // Overlapping: the witness is b's corner deepest along -axis (inside a).
    const Corners cb = corners(b);
    Vec2 deepest = cb.p[0];
    for (int k = 1; k < 4; ++k)
        if (dot(cb.p[k], sat.axis) < dot(deepest, sat.axis)) deepest = cb.p[k];
    return {sat.gap, sat.axis, deepest};
}

}  // namespace dragon
