// The stepper's second-order bounds rest on exact corner-gap rates: check them against central
// differences of the distances along real runs, and the step formula against its definition.
#include <gtest/gtest.h>

#include <cmath>

#include "core/corner_gaps.hpp"
#include "core/motion.hpp"
#include "dragon/chain.hpp"
#include "dragon/collision.hpp"

using namespace dragon;

TEST(CornerGaps, RatesMatchCentralDifferences) {
    const Simulation sim(Scenario{});
    const double h = 1e-5;
    int checked = 0;
    for (double t : {50.0, 200.0, 350.0, 412.0}) {
        const Frame f = sim.frame(t), before = sim.frame(t - h), after = sim.frame(t + h);
        const auto motion = bench_motions(f);
        for (const auto& [a, b] : candidate_pairs(f, 0.3)) {
            const size_t i = static_cast<size_t>(a - 1), j = static_cast<size_t>(b - 1);
            const auto now = corner_gaps(f.benches[i], motion[i], f.benches[j], motion[j]);
            const auto m0 = bench_motions(before), m1 = bench_motions(after);
            const auto g0 = corner_gaps(before.benches[i], m0[i], before.benches[j], m0[j]);
            const auto g1 = corner_gaps(after.benches[i], m1[i], after.benches[j], m1[j]);
            for (size_t q = 0; q < 8; ++q) {
                if (now[q].distance < 1e-3) continue;  // inside or touching: no rate to speak of
                EXPECT_NEAR(now[q].rate, (g1[q].distance - g0[q].distance) / (2 * h), 1e-6)
                    << "t " << t << " benches " << a << ", " << b << " corner " << q;
                ++checked;
            }
        }
    }
    EXPECT_GT(checked, 1000);
}

TEST(CornerGaps, SecondOrderStepIsTheRootOfTheBound) {
    for (double d : {1e-12, 1e-6, 0.01, 0.3})
        for (double rate : {-2.0, -1e-3, 0.0, 1e-3, 2.0})
            for (double m : {1e-3, 0.5, 10.0}) {
                const double h = second_order_step(d, rate, m);
                ASSERT_GT(h, 0.0);
                EXPECT_NEAR(d + rate * h - 0.5 * m * h * h, 0.0, 1e-12 * (1.0 + d + std::abs(rate) * h));
                // Just short of it the bound is still positive.
                EXPECT_GT(d + rate * 0.999 * h - 0.5 * m * 0.999 * h * 0.999 * h, 0.0);
            }
    EXPECT_EQ(second_order_step(0.0, 1.0, 1.0), 0.0);
}
