#include "motion.hpp"

#include <algorithm>
#include <cmath>
#include "dragon/portable_math.hpp"

namespace dragon {

std::vector<BenchMotion> bench_motions(const Frame& f) {
    std::vector<BenchMotion> out;
    bench_motions_into(f, out);
    return out;
}

void bench_motions_into(const Frame& f, std::vector<BenchMotion>& out) {
    out.resize(f.benches.size());
    for (size_t k = 0; k < f.benches.size(); ++k) {
        const Handle& front = f.handles[k];
        const Handle& rear = f.handles[k + 1];
        const Vec2 vf = front.speed * front.tangent, vr = rear.speed * rear.tangent;
        const Vec2 d = front.pos - rear.pos;
        const double len2 = dot(d, d);
        out[k] = {f.benches[k].centre, 0.5 * (vf + vr), cross(d, vf - vr) / len2};
    }
}

double separation_rate_bound(const Rect& a, const BenchMotion& ma, const BenchMotion& mb, double gap) {
    const Corners c = corners(a);
    double worst = 0.0;
    for (const Vec2& p : c.p) worst = std::max(worst, norm(mb.at(p) - ma.at(p)));
    return worst + std::abs(mb.omega) * std::max(gap, 0.0);
}

Radial radial_extent(const Rect& r, const BenchMotion& m) {
    // Nearest point: the origin's distance to the rectangle, in the rectangle's own frame.
    const double along = std::max(std::abs(dot(r.centre, r.axis)) - r.half_length, 0.0);
    const double across = std::max(std::abs(cross(r.axis, r.centre)) - r.half_width, 0.0);
    double hi = 0.0;
    for (const Vec2& p : corners(r).p) hi = std::max(hi, norm(p));  // the farthest point is a corner
    return {math::hypot(along, across), hi, norm(m.v_centre - m.omega * perp(m.centre))};
}

double max_point_speed(const Rect& r, const BenchMotion& m) {
    return norm(m.v_centre) + std::abs(m.omega) * math::hypot(r.half_length, r.half_width);
}

}  // namespace dragon
