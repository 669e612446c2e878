#include "core/corner_gaps.hpp"

#include <algorithm>
#include <cmath>

namespace dragon {

namespace {

// Distance from p to rectangle r and the nearest point of r.
struct Nearest {
    double distance;
    Vec2 point;
};
Nearest nearest_on(const Rect& r, Vec2 p) {
    const Vec2 n = perp(r.axis);
    const Vec2 w = p - r.centre;
    const double x = dot(w, r.axis), y = dot(w, n);
    const double cx = std::clamp(x, -r.half_length, r.half_length);
    const double cy = std::clamp(y, -r.half_width, r.half_width);
    return {std::sqrt((x - cx) * (x - cx) + (y - cy) * (y - cy)), r.centre + cx * r.axis + cy * n};
}

CornerGap gap_of(Vec2 corner, const BenchMotion& own, const Rect& other, const BenchMotion& other_motion) {
    const Nearest q = nearest_on(other, corner);
    if (q.distance <= 0.0) return {0.0, 0.0};
    const Vec2 dir = (corner - q.point) / q.distance;
    return {q.distance, dot(own.at(corner) - other_motion.at(q.point), dir)};
}

}  // namespace

std::array<CornerGap, 8> corner_gaps(const Rect& a, const BenchMotion& ma, const Rect& b, const BenchMotion& mb) {
    const Corners ca = corners(a), cb = corners(b);
    std::array<CornerGap, 8> out;
    for (int k = 0; k < 4; ++k) {
        out[static_cast<size_t>(k)] = gap_of(ca.p[k], ma, b, mb);
        out[static_cast<size_t>(k + 4)] = gap_of(cb.p[k], mb, a, ma);
    }
    return out;
}

double second_order_step(double distance, double rate, double curvature) {
    if (distance <= 0.0) return 0.0;
    // The positive root of d + r h - c h^2 / 2, written to avoid cancellation when r < 0.
    const double disc = std::sqrt(rate * rate + 2.0 * curvature * distance);
    return rate >= 0.0 ? (rate + disc) / curvature : 2.0 * distance / (disc - rate);
}

}  // namespace dragon
