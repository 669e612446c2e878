// Q5: the largest head speed under the handle speed limit, confirmed by dense scans.
#include <cmath>

#include <gtest/gtest.h>

#include "dragon/turnaround.hpp"

using namespace dragon;

namespace {

Scenario turnaround_scenario() {
    Scenario s;
    s.path.kind = PathKind::turnaround;
    return s;
}

}  // namespace

TEST(MaxSpeed, IsConfirmedByADenseScanAroundIt) {
    const Scenario sc = turnaround_scenario();
    const MaxSpeed m = max_head_speed(sc, 2.0);
    EXPECT_NEAR(m.max_head_speed * m.ratio, 2.0, 1e-14);
    EXPECT_GT(m.ratio, 1.0);
    EXPECT_GE(m.time, -100.0);
    EXPECT_LE(m.time, 100.0);
    const TurnaroundPath path(design_s_curve(sc));
    const SpeedRatio at = speed_ratio_at(path, sc.bench, m.head_arc);
    EXPECT_NEAR(at.ratio, m.ratio, 1e-15);
    // Within 1 s either side at 1 ms: nothing above the answer, and a sample close to it.
    double best = 0.0;
    for (int k = -1000; k <= 1000; ++k) {
        const double r = speed_ratio_at(path, sc.bench, m.head_arc + 1e-3 * k).ratio;
        EXPECT_LE(r, m.ratio + 1e-12) << "at s = " << m.head_arc + 1e-3 * k;
        best = std::max(best, r);
    }
    EXPECT_GT(best, m.ratio - 1e-5);
    // And finer still at 1 us around the refined moment.
    for (int k = -1000; k <= 1000; ++k)
        EXPECT_LE(speed_ratio_at(path, sc.bench, m.head_arc + 1e-6 * k).ratio, m.ratio + 1e-13);
}

TEST(MaxSpeed, NoSampleOfTheWholeRunIsFaster) {
    const Scenario sc = turnaround_scenario();
    const MaxSpeed m = max_head_speed(sc, 2.0);
    const TurnaroundPath path(design_s_curve(sc));
    for (double s = -100.0; s <= 100.0; s += 0.01)
        ASSERT_LE(speed_ratio_at(path, sc.bench, s).ratio, m.ratio + 1e-12) << "at s = " << s;
}

TEST(MaxSpeed, ScalesWithTheLimitAndNotWithTheHeadSpeed) {
    Scenario sc = turnaround_scenario();
    const MaxSpeed two = max_head_speed(sc, 2.0);
    const MaxSpeed three = max_head_speed(sc, 3.0);
    EXPECT_NEAR(three.max_head_speed, 1.5 * two.max_head_speed, 1e-12);
    // The window is head travel, so at any head speed the answer is the same but for the clock:
    // bit for bit, and its time scaled by 1 / speed.
    for (const double v : {0.05, 2.0, 5.0}) {
        sc.head_speed = v;
        const MaxSpeed m = max_head_speed(sc, 2.0);
        EXPECT_EQ(m.ratio, two.ratio) << v;
        EXPECT_EQ(m.max_head_speed, two.max_head_speed) << v;
        EXPECT_EQ(m.tied, two.tied) << v;
        EXPECT_EQ(m.travel, two.travel) << v;
        EXPECT_EQ(m.time, two.travel / v) << v;
        EXPECT_EQ(m.window.from_travel, -100.0) << v;
        EXPECT_EQ(m.window.to, 100.0 / v) << v;
    }
    // A window in seconds is that much head travel at the scenario's speed.
    sc.head_speed = 2.0;
    const MaxSpeed seconds = max_head_speed(sc, 2.0, {Along::seconds(-50.0), Along::seconds(50.0)});
    EXPECT_EQ(seconds.ratio, two.ratio);
    EXPECT_EQ(seconds.travel, two.travel);
}

TEST(MaxSpeed, RejectsBadInput) {
    const Scenario sc = turnaround_scenario();
    EXPECT_THROW(max_head_speed(sc, 0.0), InputError);
    EXPECT_THROW(max_head_speed(sc, -2.0), InputError);
    EXPECT_THROW(max_head_speed(sc, 2.0, {Along::seconds(10.0), Along::seconds(-10.0)}), InputError);
    EXPECT_THROW(max_head_speed(sc, 2.0, {Along::metres(NAN), Along::metres(10.0)}), InputError);
    EXPECT_THROW(max_head_speed(sc, 2.0, {Along::metres(0.0), Along::metres(INFINITY)}), InputError);
}
