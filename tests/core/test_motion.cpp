// The stepper's radial bound: each bench's radii [lo, hi] and the speed bound on them, checked
// against sampled points of the rectangles and central differences of material points' radii,
// on the spiral and across the turnaround path's arcs (where the chain no longer turns about
// the origin and the bound is at its loosest).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/motion.hpp"
#include "dragon/chain.hpp"

using namespace dragon;

namespace {

struct Case {
    PathKind kind;
    double t;
};
const Case kCases[] = {{PathKind::spiral, 0.0},      {PathKind::spiral, 250.0},     {PathKind::spiral, 412.0},
                       {PathKind::turnaround, -30.0}, {PathKind::turnaround, 3.0},   {PathKind::turnaround, 8.0},
                       {PathKind::turnaround, 14.0},  {PathKind::turnaround, 60.0}};

Simulation simulation(PathKind kind) {
    Scenario s;
    s.path.kind = kind;
    return Simulation(s);
}

// A point of the rectangle by its own coordinates: u along the axis, w across, both in [-1, 1].
Vec2 point_of(const Rect& r, double u, double w) {
    return r.centre + (u * r.half_length) * r.axis + (w * r.half_width) * perp(r.axis);
}

// Distance from the origin to the segment [p, q], independently of the rectangle's frame.
double distance_to_segment(const Vec2& p, const Vec2& q) {
    const Vec2 d = q - p;
    const double s = std::clamp(-dot(p, d) / dot(d, d), 0.0, 1.0);
    return norm(p + s * d);
}

}  // namespace

TEST(RadialExtent, BracketsEveryPointOfTheBench) {
    int checked = 0;
    for (const Case& c : kCases) {
        const Frame f = simulation(c.kind).frame(c.t);
        const auto motion = bench_motions(f);
        for (size_t k = 0; k < f.benches.size(); ++k) {
            const Rect& r = f.benches[k];
            const Radial e = radial_extent(r, motion[k]);
            double far = 0.0;
            for (int i = 0; i <= 40; ++i)
                for (int j = 0; j <= 6; ++j) {
                    const double radius = norm(point_of(r, -1.0 + i / 20.0, -1.0 + j / 3.0));
                    EXPECT_LE(e.lo, radius + 1e-12) << "bench " << k + 1 << " t " << c.t;
                    EXPECT_GE(e.hi, radius - 1e-12) << "bench " << k + 1 << " t " << c.t;
                    far = std::max(far, radius);
                }
            // The corners are among the samples, and the nearest point lies on an edge (the
            // origin is never inside a bench here).
            EXPECT_NEAR(e.hi, far, 1e-12);
            const Corners q = corners(r);
            double near = INFINITY;
            for (int i = 0; i < 4; ++i) near = std::min(near, distance_to_segment(q.p[i], q.p[(i + 1) % 4]));
            EXPECT_NEAR(e.lo, near, 1e-12) << "bench " << k + 1 << " t " << c.t;
            ++checked;
        }
    }
    EXPECT_EQ(checked, 8 * 223);
}

TEST(RadialExtent, NoPointsRadiusChangesFasterThanTheBound) {
    const double h = 1e-5;
    double largest_ratio = 0.0;
    for (const Case& c : kCases) {
        const Simulation sim = simulation(c.kind);
        const Frame f = sim.frame(c.t), before = sim.frame(c.t - h), after = sim.frame(c.t + h);
        const auto motion = bench_motions(f);
        for (size_t k = 0; k < f.benches.size(); ++k) {
            const Radial e = radial_extent(f.benches[k], motion[k]);
            for (double u : {-1.0, -0.5, 0.0, 0.5, 1.0})
                for (double w : {-1.0, 0.0, 1.0}) {
                    // The same material point of the bench at t - h and t + h.
                    const double rate =
                        (norm(point_of(after.benches[k], u, w)) - norm(point_of(before.benches[k], u, w))) / (2 * h);
                    EXPECT_LE(std::abs(rate), e.speed + 1e-6) << "bench " << k + 1 << " t " << c.t;
                    if (e.speed > 1e-3) largest_ratio = std::max(largest_ratio, std::abs(rate) / e.speed);
                }
        }
    }
    // Not vacuous: somewhere a point's radius does change at a good part of the bound.
    EXPECT_GT(largest_ratio, 0.5);
}
