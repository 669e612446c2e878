// Exact handle speeds on the turnaround path against finite differences of the positions,
// including handles crossing the joins, and the simulation's timeline (t = 0 at the turn).
#include <cmath>

#include <gtest/gtest.h>

#include "dragon/chain.hpp"
#include "dragon/turnaround.hpp"

using namespace dragon;

namespace {

Scenario turnaround_scenario() {
    Scenario s;
    s.path.kind = PathKind::turnaround;
    return s;
}

}  // namespace

TEST(TurnaroundSpeed, ExactSpeedsMatchFiniteDifferences) {
    const Scenario sc = turnaround_scenario();
    const TurnaroundPath path(design_s_curve(sc));
    const double h = 1e-5;  // central difference: error ~h^2 |P'''| plus 1e-16 / h of rounding
    Frame a, m, b;
    for (double s = -10.0; s <= 60.0; s += 0.0917) {
        solve_chain(path, sc.bench, s - h, 1.0, a);
        solve_chain(path, sc.bench, s, 1.0, m);
        solve_chain(path, sc.bench, s + h, 1.0, b);
        for (size_t i = 0; i < m.handles.size(); ++i) {
            const Vec2 v = (b.handles[i].pos - a.handles[i].pos) / (2.0 * h);
            EXPECT_NEAR(norm(v), m.handles[i].speed, 1e-7) << "s = " << s << ", handle " << i;
            EXPECT_GT(dot(v, m.handles[i].tangent), 0.0);
        }
    }
}

// Handle k exactly on a join: the head's arc position found by bisection (a handle's arc
// position grows with the head's), then differences straddling the crossing.
TEST(TurnaroundSpeed, SpeedsOfHandlesCrossingJoinsMatchFiniteDifferences) {
    const Scenario sc = turnaround_scenario();
    const TurnaroundPath path(design_s_curve(sc));
    const double h = 1e-6;
    Frame a, m, b;
    for (int piece = 1; piece <= 3; ++piece) {
        for (size_t k = 0; k <= 6; ++k) {
            const double join = path.join_arc(piece);
            double lo = join, hi = join + 2.86 + 1.65 * static_cast<double>(k) * 1.5;
            for (int it = 0; it < 200 && hi - lo > 1e-14; ++it) {
                const double mid = 0.5 * (lo + hi);
                solve_chain(path, sc.bench, mid, 1.0, m);
                (path.arc(m.handles[k].place) < join ? lo : hi) = mid;
            }
            solve_chain(path, sc.bench, lo - h, 1.0, a);
            solve_chain(path, sc.bench, lo, 1.0, m);
            solve_chain(path, sc.bench, lo + h, 1.0, b);
            ASSERT_NEAR(path.arc(m.handles[k].place), join, 1e-9);
            EXPECT_NE(a.handles[k].place.piece, b.handles[k].place.piece);
            for (size_t i = 0; i <= k + 2; ++i) {
                const Vec2 v = (b.handles[i].pos - a.handles[i].pos) / (2.0 * h);
                EXPECT_NEAR(norm(v), m.handles[i].speed, 1e-6)
                    << "join " << piece << ", handle " << k << " on it, handle " << i;
            }
        }
    }
}

TEST(TurnaroundSpeed, SimulationStartsTheTurnAtTimeZero) {
    Scenario sc = turnaround_scenario();
    sc.head_speed = 1.3;
    const Simulation sim(sc);
    const SCurve d = design_s_curve(sc);
    EXPECT_NEAR(distance(sim.frame(0.0).handles[0].pos, d.entry), 0.0, 1e-12);
    EXPECT_EQ(sim.frame(-1e-6).handles[0].place.piece, 0);
    EXPECT_EQ(sim.frame(1e-6).handles[0].place.piece, 1);
    EXPECT_NEAR(distance(sim.frame(d.length / 1.3).handles[0].pos, d.exit), 0.0, 1e-12);
    const Frame f = sim.frame(-100.0);
    EXPECT_EQ(f.handles.size(), 224u);
    EXPECT_DOUBLE_EQ(f.handles[0].speed, 1.3);
    EXPECT_NO_THROW(sim.frame(100.0));
}

TEST(TurnaroundSpeed, BadScenariosAreInputErrors) {
    Scenario sc = turnaround_scenario();
    sc.path.arc_ratio = 0.0;
    EXPECT_THROW(Simulation{sc}, InputError);
    sc = turnaround_scenario();
    sc.path.turn_radius = -4.5;
    EXPECT_THROW(Simulation{sc}, InputError);
}
