// The library's own elementary functions (dragon/portable_math.hpp) measured against long
// double's (64-bit significands: a reference 2^-11 of a double's ulp away at most): the error
// in ulps over random arguments of the ranges the library meets, and the special values.
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "dragon/portable_math.hpp"

namespace {

// |got - want| in units of the last place of the double nearest want.
double ulps(double got, long double want) {
    const double w = static_cast<double>(want);
    const double ulp = std::nextafter(std::fabs(w), std::numeric_limits<double>::infinity()) - std::fabs(w);
    return static_cast<double>(std::fabs(static_cast<long double>(got) - want) / ulp);
}

struct Worst {
    double ulps = 0, at = 0;
};

Worst worst_over(const std::function<double(double)>& mine, const std::function<long double(long double)>& ref,
                 double lo, double hi, bool log_spaced, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Worst w;
    for (int i = 0; i < 200000; ++i) {
        const double x = log_spaced ? lo * std::pow(hi / lo, u(rng)) : lo + (hi - lo) * u(rng);
        const double e = ulps(mine(x), ref(x));
        if (e > w.ulps) w = {e, x};
    }
    return w;
}

TEST(PortableMath, SinAndCosWithinAnUlp) {
    for (const auto& [lo, hi] : {std::pair{-1.0, 1.0}, std::pair{-100.0, 100.0}, std::pair{-7e4, 7e4}}) {
        const Worst s = worst_over(dragon::math::sin, [](long double x) { return std::sin(x); }, lo, hi, false, 1);
        const Worst c = worst_over(dragon::math::cos, [](long double x) { return std::cos(x); }, lo, hi, false, 2);
        EXPECT_LE(s.ulps, 1.0) << "sin at " << s.at;
        EXPECT_LE(c.ulps, 1.0) << "cos at " << c.at;
    }
    // Near multiples of pi/2, where the reduction cancels most.
    for (int n = -40000; n <= 40000; n += 7) {
        const double x = std::nextafter(n * 1.5707963267948966, 0.0);
        EXPECT_LE(ulps(dragon::math::sin(x), std::sin(static_cast<long double>(x))), 1.0) << x;
        EXPECT_LE(ulps(dragon::math::cos(x), std::cos(static_cast<long double>(x))), 1.0) << x;
    }
}

TEST(PortableMath, TanWithinAnUlp) {
    const Worst t = worst_over(dragon::math::tan, [](long double x) { return std::tan(x); }, -1.5, 1.5, false, 3);
    EXPECT_LE(t.ulps, 1.0) << "tan at " << t.at;
    const Worst w = worst_over(dragon::math::tan, [](long double x) { return std::tan(x); }, -1e3, 1e3, false, 4);
    EXPECT_LE(w.ulps, 1.0) << "tan at " << w.at;
}

TEST(PortableMath, ArcTangentsAndArcSineWithinTheirBounds) {
    const Worst a = worst_over(dragon::math::atan, [](long double x) { return std::atan(x); }, -4.0, 4.0, false, 5);
    EXPECT_LE(a.ulps, 1.0) << "atan at " << a.at;
    const Worst big = worst_over(dragon::math::atan, [](long double x) { return std::atan(x); }, 1e-300, 1e300, true, 6);
    EXPECT_LE(big.ulps, 1.0) << "atan at " << big.at;
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-10.0, 10.0);
    double worst = 0, at_y = 0, at_x = 0;
    for (int i = 0; i < 200000; ++i) {
        const double y = u(rng), x = u(rng);
        const double e = ulps(dragon::math::atan2(y, x), std::atan2(static_cast<long double>(y), static_cast<long double>(x)));
        if (e > worst) worst = e, at_y = y, at_x = x;
    }
    EXPECT_LE(worst, 1.5) << "atan2 at " << at_y << ", " << at_x;
    const Worst s = worst_over(dragon::math::asin, [](long double x) { return std::asin(x); }, -1.0, 1.0, false, 8);
    EXPECT_LE(s.ulps, 2.5) << "asin at " << s.at;
}

TEST(PortableMath, HypotLog1pAndAsinhWithinAnUlp) {
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> e(-300.0, 300.0), u(-1.0, 1.0);
    double worst = 0;
    for (int i = 0; i < 200000; ++i) {
        const double x = u(rng) * std::pow(10.0, e(rng) / 10), y = u(rng) * std::pow(10.0, e(rng) / 10);
        worst = std::max(worst, ulps(dragon::math::hypot(x, y), std::hypot(static_cast<long double>(x), static_cast<long double>(y))));
    }
    EXPECT_LE(worst, 1.0) << "hypot";
    const Worst l = worst_over(dragon::math::log1p, [](long double x) { return std::log1p(x); }, -0.999, 1e6, false, 10);
    EXPECT_LE(l.ulps, 1.0) << "log1p at " << l.at;
    const Worst small = worst_over(dragon::math::log1p, [](long double x) { return std::log1p(x); }, 1e-20, 0.5, true, 11);
    EXPECT_LE(small.ulps, 1.0) << "log1p at " << small.at;
    const Worst h = worst_over(dragon::math::asinh, [](long double x) { return std::asinh(x); }, 1e-12, 1e12, true, 12);
    EXPECT_LE(h.ulps, 1.0) << "asinh at " << h.at;
    const Worst hn = worst_over(dragon::math::asinh, [](long double x) { return std::asinh(x); }, -1e5, 1e5, false, 13);
    EXPECT_LE(hn.ulps, 1.0) << "asinh at " << hn.at;
}

TEST(PortableMath, SpecialValuesAreCs) {
    const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_TRUE(std::isnan(dragon::math::sin(inf)));
    EXPECT_TRUE(std::isnan(dragon::math::cos(nan)));
    EXPECT_TRUE(std::signbit(dragon::math::sin(-0.0)));
    EXPECT_EQ(dragon::math::cos(0.0), 1.0);
    EXPECT_EQ(dragon::math::atan(inf), std::atan(inf));
    EXPECT_EQ(dragon::math::atan2(0.0, -1.0), std::atan2(0.0, -1.0));
    EXPECT_EQ(dragon::math::atan2(-0.0, -1.0), std::atan2(-0.0, -1.0));
    EXPECT_EQ(dragon::math::atan2(1.0, 0.0), std::atan2(1.0, 0.0));
    EXPECT_EQ(dragon::math::atan2(-inf, -inf), std::atan2(-inf, -inf));
    EXPECT_EQ(dragon::math::atan2(inf, 1.0), std::atan2(inf, 1.0));
    EXPECT_EQ(dragon::math::atan2(1.0, -inf), std::atan2(1.0, -inf));
    EXPECT_TRUE(std::signbit(dragon::math::atan2(-0.0, 1.0)));
    EXPECT_TRUE(std::isnan(dragon::math::asin(1.5)));
    EXPECT_EQ(dragon::math::asin(1.0), std::asin(1.0));
    EXPECT_EQ(dragon::math::hypot(inf, nan), inf);
    EXPECT_EQ(dragon::math::hypot(3.0, 4.0), 5.0);
    EXPECT_EQ(dragon::math::hypot(1e300, 1e300), std::hypot(1e300, 1e300));
    EXPECT_EQ(dragon::math::log1p(-1.0), -inf);
    EXPECT_TRUE(std::isnan(dragon::math::log1p(-2.0)));
    EXPECT_EQ(dragon::math::asinh(-inf), -inf);
    EXPECT_EQ(dragon::math::asinh(0.0), 0.0);
}

}  // namespace
