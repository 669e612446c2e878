#include "corner_gaps.hpp"

#include <algorithm>
#include <cmath>

namespace dragon {

namespace {


CornerGap gap_of(const Vec2& corner, const BenchMotion& own, const Rect& other, const BenchMotion& other_motion) {
    const PointToRect q = point_to_rect(corner, other);
    if (q.distance <= 0.0) return {0.0, 0.0};
    const Vec2 dir = (corner - q.nearest) / q.distance;
    return {q.distance, dot(own.at(corner) - other_motion.at(q.nearest), dir)};
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
