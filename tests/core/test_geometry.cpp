// The plane geometry on Eigen: the named operations agree with Eigen's own, and every value type
// with a Vec2 in it starts at zero (Eigen alone would leave it unset).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <type_traits>

#include <Eigen/Geometry>

#include "dragon/analyses.hpp"
#include "dragon/chain.hpp"
#include "dragon/collision.hpp"
#include "dragon/geometry.hpp"
#include "dragon/path.hpp"
#include "dragon/turnaround.hpp"

using namespace dragon;

static_assert(std::is_same_v<Vec2, Eigen::Vector2d>, "a caller's Eigen code takes the library's points as they are");

TEST(Geometry, NamedOperationsAgreeWithEigen) {
    const Vec2 a{3.0, -4.0}, b{-1.5, 2.25};
    EXPECT_EQ(dot(a, b), a.x() * b.x() + a.y() * b.y());
    // cross is the z of the 3-D cross product, and perp the quarter turn Eigen's rotation gives.
    const Eigen::Vector3d a3{a.x(), a.y(), 0.0}, b3{b.x(), b.y(), 0.0};
    EXPECT_EQ(cross(a, b), a3.cross(b3).z());
    const Vec2 quarter = Eigen::Rotation2Dd(std::numbers::pi / 2) * a;
    EXPECT_NEAR(perp(a).x(), quarter.x(), 1e-15);
    EXPECT_NEAR(perp(a).y(), quarter.y(), 1e-15);
    EXPECT_EQ(norm(a), 5.0);
    EXPECT_EQ(distance(a, a + Vec2{0.0, 2.0}), 2.0);
    EXPECT_DOUBLE_EQ(norm(normalized(b)), 1.0);
}

TEST(Geometry, ValueTypesStartAtZero) {
    const auto zero = [](const Vec2& v) { return v.x() == 0.0 && v.y() == 0.0; };
    const Rect r;
    EXPECT_TRUE(zero(r.centre) && zero(r.axis));
    const Handle h{};
    EXPECT_TRUE(zero(h.pos) && zero(h.tangent));
    const Located l{};
    EXPECT_TRUE(zero(l.pos) && zero(l.tangent));
    const Separation s{};
    EXPECT_TRUE(zero(s.axis) && zero(s.point));
    const Clearance c{};
    EXPECT_TRUE(zero(c.axis) && zero(c.point));
    const Contact k{};
    EXPECT_TRUE(zero(k.point));
    const SCurve d{};
    EXPECT_TRUE(zero(d.entry) && zero(d.exit) && zero(d.direction) && zero(d.c1) && zero(d.c2) && zero(d.joint));
}

TEST(Geometry, PointToRectMatchesTheBoardsOwnFrame) {
    // A board turned 30 degrees: the distance measured in its own frame (by Eigen's rotation)
    // equals point_to_rect's.
    const double phi = std::numbers::pi / 6;
    const Rect r{{1.0, 2.0}, {std::cos(phi), std::sin(phi)}, 1.1, 0.15};
    const Eigen::Rotation2Dd to_board(-phi);
    for (const Vec2& p : {Vec2{4.0, 2.0}, Vec2{1.2, 2.1}, Vec2{-3.0, -1.0}, Vec2{1.0, 3.0}}) {
        const Vec2 local = to_board * (p - r.centre);
        const Vec2 half{r.half_length, r.half_width};
        const Vec2 outside = (local.cwiseAbs() - half).cwiseMax(0.0);
        EXPECT_NEAR(point_to_rect(p, r).distance, outside.norm(), 1e-14) << p.transpose();
    }
}
