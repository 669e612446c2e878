// Is the default turnaround collision-free, and how close do the benches come?
#include <gtest/gtest.h>

#include "dragon/analyses.hpp"
#include "dragon/collision.hpp"
#include "dragon/turnaround.hpp"

using namespace dragon;

TEST(TurnaroundClearance, DefaultRunIsCollisionFreeAndItsMinimumIsConfirmed) {
    Scenario sc;
    sc.path.kind = PathKind::turnaround;
    const RunClearance c = min_clearance(sc);
    EXPECT_TRUE(c.collision_free());
    EXPECT_GT(c.distance, 0.0);
    EXPECT_GE(c.time, -100.0);
    EXPECT_LE(c.time, 100.0);
    EXPECT_GE(c.bench_b, c.bench_a + 2);

    const Simulation sim(sc);
    // The reported pair and distance against every pair at that moment.
    const Clearance exact = clearance_all_pairs(sim.frame(c.time));
    EXPECT_NEAR(exact.distance, c.distance, 1e-12);
    // A dense scan around the moment finds nothing closer.
    double best = 1e300;
    for (int k = -500; k <= 500; ++k) {
        const double t = c.time + 1e-3 * k;
        const double d = clearance(sim.frame(t), 1.0).distance;
        EXPECT_GE(d, c.distance - 1e-12) << "t = " << t;
        best = std::min(best, d);
    }
    EXPECT_LT(best, c.distance + 1e-6);
    // The exact first-contact search agrees that the run is collision-free.
    EXPECT_FALSE(first_contact(sim, -100.0, 100.0).has_value());
}
