// The S-curve design against independent constructions, and the Q4 length study.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "dragon/turnaround.hpp"

using namespace dragon;

namespace {

constexpr double kPi = 3.141592653589793238462643383279;

// The coil-in spiral's travel direction at theta by central differences of its points (no use of
// the library's tangent formula).
Vec2 numeric_direction(double b, double theta) {
    auto p = [b](double t) { return Vec2{b * t * std::cos(t), b * t * std::sin(t)}; };
    const double h = 1e-6;
    return normalized(p(theta - h) - p(theta + h));  // travel: theta decreasing
}

// r2 by bisection on the tangency residual |C1 - C2| - (r1 + r2), the centres built from the
// numeric direction: arc 1 to the right of the travel at A, arc 2 to the left at B = -A.
double bisected_r2(double pitch, double radius, double ratio) {
    const double b = pitch / (2.0 * kPi);
    const double theta = radius / b;
    const Vec2 a{radius * std::cos(theta), radius * std::sin(theta)};
    const Vec2 t = numeric_direction(b, theta);  // the same at B by point symmetry
    const Vec2 left = perp(t);
    auto residual = [&](double r2) {
        const Vec2 c1 = a - ratio * r2 * left;
        const Vec2 c2 = -a + r2 * left;
        return distance(c1, c2) - (ratio + 1.0) * r2;
    };
    double lo = 1e-9, hi = 10.0 * radius;
    EXPECT_GT(residual(lo), 0.0);
    EXPECT_LT(residual(hi), 0.0);
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        (residual(mid) > 0.0 ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

// The S-curve's length as the length of a fine polyline through its points (at() only).
double polyline_length(const TurnaroundPath& path) {
    double total = 0.0;
    for (int piece : {1, 2}) {
        const auto [u0, u1] = path.piece_range(piece);
        const int n = 200000;
        Vec2 prev = path.at({piece, u0}).pos;
        for (int i = 1; i <= n; ++i) {
            const Vec2 p = path.at({piece, u0 + (u1 - u0) * i / n}).pos;
            total += distance(prev, p);
            prev = p;
        }
    }
    return total;
}

}  // namespace

TEST(TurnaroundDesign, MatchesAnIndependentConstructionForSeveralRatios) {
    for (double ratio : {0.5, 1.0, 2.0, 3.0, 7.5}) {
        SCOPED_TRACE(ratio);
        const SCurve d = design_s_curve(1.7, 4.5, ratio);
        // Finite-difference directions are good to ~1e-10, so r2 agrees to about that.
        EXPECT_NEAR(d.r2, bisected_r2(1.7, 4.5, ratio), 1e-8);
        EXPECT_NEAR(d.r1, ratio * d.r2, 1e-14);
        EXPECT_NEAR(distance(d.c1, d.c2), d.r1 + d.r2, 1e-12);
        EXPECT_NEAR(distance(d.entry, d.c1), d.r1, 1e-12);
        EXPECT_NEAR(distance(d.exit, d.c2), d.r2, 1e-12);
        EXPECT_NEAR(distance(d.joint, d.c1), d.r1, 1e-12);
        EXPECT_NEAR(distance(d.joint, d.c2), d.r2, 1e-12);
        EXPECT_NEAR(norm(d.entry), 4.5, 1e-12);
        EXPECT_NEAR(distance(d.exit, -d.entry), 0.0, 1e-15);
        // Radii at A and B are perpendicular to the travel (tangency to the spirals).
        EXPECT_NEAR(dot(d.entry - d.c1, d.direction), 0.0, 1e-12);
        EXPECT_NEAR(dot(d.exit - d.c2, d.direction), 0.0, 1e-12);
        // The length by a polyline through the path's points.
        const TurnaroundPath path(d);
        EXPECT_NEAR(polyline_length(path), d.length, 1e-8);
    }
}

// Closed form of the symmetric case: r1 + r2 = R sqrt(1 + theta^2) / theta and each arc sweeps
// alpha with cos(alpha) = 1 - 2 theta^2 / (1 + theta^2), for any ratio.
TEST(TurnaroundDesign, LengthIsTheSameForEveryRatio) {
    for (double pitch : {1.7, 0.9, 2.5}) {
        for (double radius : {4.5, 3.0}) {
            const double theta = radius * 2.0 * kPi / pitch;
            const double sum = radius * std::sqrt(1.0 + theta * theta) / theta;
            const double alpha = std::acos(1.0 - 2.0 * theta * theta / (1.0 + theta * theta));
            for (double ratio : {0.3, 1.0, 2.0, 4.0}) {
                const SCurve d = design_s_curve(pitch, radius, ratio);
                EXPECT_NEAR(d.r1 + d.r2, sum, 1e-12);
                EXPECT_NEAR(d.angle1, alpha, 1e-7);  // acos loses half the digits near -1
                EXPECT_NEAR(d.angle2, d.angle1, 1e-12);
                EXPECT_NEAR(d.length, sum * alpha, 1e-6);
            }
        }
    }
}

// max_radius against a dense sampling of the S-curve, for ratios that put the farthest point
// at an end and inside an arc.
TEST(TurnaroundDesign, FarthestPointMatchesSampling) {
    for (double ratio : {0.25, 1.0, 2.0, 10.0}) {
        for (double radius : {4.5, 2.0}) {
            const SCurve d = design_s_curve(1.7, radius, ratio);
            const TurnaroundPath path(d);
            double far = 0.0;
            for (int i = 0; i <= 100000; ++i) far = std::max(far, norm(path.at_arc(d.length * i / 100000).pos));
            EXPECT_NEAR(far, d.max_radius, 1e-6) << "ratio " << ratio << ", radius " << radius;
        }
    }
    EXPECT_LE(design_s_curve(1.7, 4.5, 2.0).max_radius, 4.5 + 1e-12);
}

TEST(TurnaroundDesign, RejectsBadInput) {
    EXPECT_THROW(design_s_curve(1.7, 4.5, 0.0), InputError);
    EXPECT_THROW(design_s_curve(1.7, 4.5, -2.0), InputError);
    EXPECT_THROW(design_s_curve(1.7, -1.0, 2.0), InputError);
    EXPECT_THROW(design_s_curve(0.0, 4.5, 2.0), InputError);
    EXPECT_THROW(design_s_curve(1.7, std::nan(""), 2.0), InputError);
}

TEST(TurnaroundStudy, RatioDoesNotMatterAndAnInnerStartTrades) {
    Scenario s;
    const TurnaroundStudy st = study_turnaround(s);
    ASSERT_GE(st.by_ratio.size(), 5u);
    EXPECT_LT(st.ratio_spread, 1e-9);
    for (const TurnStudyRow& r : st.by_ratio) EXPECT_NEAR(r.s_curve_length, st.design.length, 1e-9);
    // Moving the entry inward shortens the S-curve but lengthens the way through the space.
    for (size_t i = 1; i < st.by_entry.size(); ++i) {
        EXPECT_LT(st.by_entry[i].entry_radius, st.by_entry[i - 1].entry_radius);
        EXPECT_LT(st.by_entry[i].s_curve_length, st.by_entry[i - 1].s_curve_length);
        EXPECT_GT(st.by_entry[i].inside_length, st.by_entry[i - 1].inside_length);
    }
    EXPECT_NEAR(st.by_entry.front().inside_length, st.design.length, 1e-9);
    // The contest's dragon follows its own design (ratio 2, entry at the boundary) all the way.
    EXPECT_FALSE(st.design_jam.has_value());
    EXPECT_TRUE(st.by_entry.front().followable());
    EXPECT_THROW(length_vs_entry_radius(1.7, 4.5, 2.0, {5.0}), InputError);
}
