// The plain spiral and the chain on it: published values, exact chords, handles on the curve,
// exact speeds against finite differences, the nearest root against a brute-force scan.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "core/chain_front.hpp"
#include "dragon/chain.hpp"
#include "dragon/path.hpp"

using namespace dragon;

namespace {

constexpr double kTwoPi = 6.283185307179586476925286766559;

struct Published {
    int handle;
    double x, y, speed;
};

// PROBLEM.md, Q1 at t = 0.
const Published kAtZero[] = {
    {0, 8.800000, 0.000000, 1.000000},     {1, 8.363824, 2.826544, 0.999971},
    {51, -9.518732, 1.341137, 0.999742},   {101, 2.913983, -9.918311, 0.999575},
    {151, 10.861726, 1.828753, 0.999448},  {201, 4.555102, 10.725118, 0.999348},
    {223, -5.305444, -10.676584, 0.999311},
};

// Angle of p reduced to be within pi of theta.
double unwrap_to(const Vec2& p, double theta) {
    double a = std::atan2(p.y(), p.x());
    return a + kTwoPi * std::round((theta - a) / kTwoPi);
}

std::vector<Scenario> sample_scenarios() {
    std::vector<Scenario> out(1);  // the contest's
    Scenario s;
    s.bench = {40, 2.5, 1.2, 0.2, 0.1};
    s.path.pitch = 0.9;
    s.path.start_turn = 9.5;
    s.head_speed = 1.7;
    out.push_back(s);
    s.bench = {12, 1.0, 3.0, 0.5, 0.4};
    s.path.pitch = 1.3;
    s.path.start_turn = 4.2;
    s.head_speed = 0.3;
    out.push_back(s);
    return out;
}

}  // namespace

TEST(Q1, PublishedValuesAtZero) {
    const Simulation sim(Scenario{});
    const Frame f = sim.frame(0.0);
    ASSERT_EQ(f.handles.size(), 224u);
    for (const Published& p : kAtZero) {
        const Handle& h = f.handles[static_cast<size_t>(p.handle)];
        EXPECT_NEAR(h.pos.x(), p.x, 5e-7) << "handle " << p.handle;
        EXPECT_NEAR(h.pos.y(), p.y, 5e-7) << "handle " << p.handle;
        EXPECT_NEAR(h.speed, p.speed, 5e-7) << "handle " << p.handle;
    }
}

TEST(Q1, PublishedHeadAt300) {
    const Simulation sim(Scenario{});
    const Frame f = sim.frame(300.0);
    EXPECT_NEAR(f.handles[0].pos.x(), 4.420274, 5e-7);
    EXPECT_NEAR(f.handles[0].pos.y(), 2.320429, 5e-7);
}

TEST(Spiral, ArcLengthRoundTrips) {
    for (double pitch : {0.3, 0.55, 1.7, 5.0}) {
        const Spiral sp(pitch);
        for (double theta : {0.0, 1e-6, 0.3, 1.0, 7.0, 100.53, 3000.0}) {
            const double len = sp.length_to(theta);
            EXPECT_NEAR(sp.theta_at_length(len), theta, 1e-12 * (1.0 + theta)) << pitch << " " << theta;
            const Located at = sp.at_arc(-len);
            EXPECT_NEAR(sp.arc(at.place), -len, 1e-12 * (1.0 + len));
        }
    }
}

TEST(Spiral, ArcLengthMatchesQuadrature) {
    // Independent: Simpson's rule on |dP/dtheta| = b sqrt(1 + theta^2).
    const Spiral sp(0.55);
    const double a = 2.0, b = 40.0;
    const int n = 20000;
    double sum = 0.0;
    for (int k = 0; k <= n; ++k) {
        const double th = a + (b - a) * k / n;
        const double w = (k == 0 || k == n) ? 1.0 : (k % 2 ? 4.0 : 2.0);
        sum += w * sp.b() * std::sqrt(1.0 + th * th);
    }
    sum *= (b - a) / n / 3.0;
    EXPECT_NEAR(sp.length_to(b) - sp.length_to(a), sum, 1e-9);
}

TEST(Chain, ChordsExactAndHandlesOnTheSpiral) {
    for (const Scenario& s : sample_scenarios()) {
        const Simulation sim(s);
        const auto& sp = static_cast<const Spiral&>(sim.path());
        for (double t : {0.0, 37.5, 0.9 * sim.end_time()}) {
            const Frame f = sim.frame(t);
            for (size_t i = 0; i < f.handles.size(); ++i) {
                const Handle& h = f.handles[i];
                const double theta = h.place.u;
                EXPECT_NEAR(norm(h.pos), sp.b() * theta, 1e-10);
                EXPECT_NEAR(unwrap_to(h.pos, theta), theta, 1e-10 / std::max(1.0, norm(h.pos)));
                if (i + 1 < f.handles.size()) {
                    EXPECT_NEAR(distance(h.pos, f.handles[i + 1].pos), s.bench.link_after(static_cast<int>(i)), 1e-10)
                        << "t " << t << " handle " << i;
                    EXPECT_GT(f.handles[i + 1].place.u, theta);  // behind = further out
                }
            }
        }
    }
}

TEST(Chain, NearestRootAgainstDenseScan) {
    // Walk outward from each handle in tiny steps of theta; the first point at the link's
    // chord distance must be the solver's next handle.
    const Simulation sim(Scenario{});
    const auto& sp = static_cast<const Spiral&>(sim.path());
    const Frame f = sim.frame(410.0);  // tight turns near the end of coiling in
    for (size_t i = 0; i + 1 < f.handles.size(); i += 7) {
        const double th = f.handles[i].place.u;
        const double d = Scenario{}.bench.link_after(static_cast<int>(i));
        const double h = 1e-4;
        double u = th;
        while (distance(sp.at({0, u + h}).pos, f.handles[i].pos) < d) u += h;
        // The root lies in (u, u + h]; refine by bisection.
        double lo = u, hi = u + h;
        for (int k = 0; k < 60; ++k) {
            const double m = 0.5 * (lo + hi);
            (distance(sp.at({0, m}).pos, f.handles[i].pos) < d ? lo : hi) = m;
        }
        EXPECT_NEAR(f.handles[i + 1].place.u, lo, 1e-11) << "handle " << i;
    }
}

TEST(Chain, TheChordMemoIsOnlyAGuess) {
    // Each link solved from the memo of the last one and again from scratch (memo cleared):
    // both reach the same root, to rounding, on every sample scenario from the start to the
    // centre. So does a memo with a poor guess, and one left over from another place.
    int with_memo = 0, links = 0;
    for (const Scenario& s : sample_scenarios()) {
        const Simulation sim(s);
        const auto& sp = static_cast<const Spiral&>(sim.path());
        for (double t : {0.0, 0.5 * sim.end_time(), sim.end_time()}) {
            Located cur = sp.at_arc(sim.head_arc(t));
            for (int i = 0; i + 1 < s.bench.handle_count(); ++i) {
                const double d = s.bench.link_after(i);
                const auto next = sp.behind(cur, d);
                Located plain = cur;
                plain.memo = {};
                const auto fresh = sp.behind(plain, d);
                Located wrong = cur;
                const double poor = 0.5 * cur.memo.angle + 0.01;
                wrong.memo = {cur.place.u, d, poor, std::cos(0.5 * poor), std::sin(0.5 * poor), 0.05};
                const auto misled = sp.behind(wrong, d);
                Located stale = cur;
                stale.memo.theta = cur.place.u - 0.1;  // made at another place
                stale.memo.angle += 0.1;
                const auto ignored = sp.behind(stale, d);
                ASSERT_TRUE(next && fresh && misled && ignored);
                with_memo += cur.memo.chord == d;
                ++links;
                const double scale = std::max(1.0, norm(fresh->pos));
                EXPECT_NEAR(next->place.u, fresh->place.u, 4e-16 * fresh->place.u) << "t " << t << " link " << i;
                EXPECT_NEAR(distance(next->pos, fresh->pos), 0.0, 1e-15 * scale) << "t " << t << " link " << i;
                EXPECT_NEAR(misled->place.u, fresh->place.u, 4e-16 * fresh->place.u) << "t " << t << " link " << i;
                EXPECT_EQ(ignored->place.u, fresh->place.u) << "t " << t << " link " << i;
                cur = *next;
            }
        }
    }
    EXPECT_GT(with_memo, 0.9 * links);  // the memo is used, not just carried
}

TEST(Chain, NearCentreUsesTheGeneralSearch) {
    // A long link on a tight spiral: the chord reaches round past the far side of the centre,
    // where the monotone bracket (0, pi] no longer holds.
    const Spiral sp(0.3);
    const Located from = sp.at({0, 1.0});
    const double d = 1.0;  // > b (2 theta + pi) = 0.24
    const auto next = sp.behind(from, d);
    ASSERT_TRUE(next.has_value());
    EXPECT_NEAR(distance(next->pos, from.pos), d, 1e-10);
    // Nothing between: every theta in (1, u) is closer than d.
    for (double u = 1.0 + 1e-3; u < next->place.u - 1e-9; u += 1e-3)
        EXPECT_LT(distance(sp.at({0, u}).pos, from.pos), d);
}

TEST(Chain, ExactSpeedsMatchFiniteDifferences) {
    for (const Scenario& s : sample_scenarios()) {
        const Simulation sim(s);
        const double h = 1e-4;
        for (double t : {0.0, 0.5 * sim.end_time(), 0.8 * sim.end_time()}) {
            const Frame f = sim.frame(t), fp = sim.frame(t + h), fm = sim.frame(t - h);
            for (size_t i = 0; i < f.handles.size(); ++i) {
                const Vec2 v = (fp.handles[i].pos - fm.handles[i].pos) / (2.0 * h);
                EXPECT_NEAR(f.handles[i].speed, norm(v), 1e-6 * s.head_speed) << "t " << t << " handle " << i;
                // The exact velocity is along the tangent.
                EXPECT_NEAR(dot(v, f.handles[i].tangent), norm(v), 1e-6 * s.head_speed);
            }
        }
    }
}

TEST(Chain, BenchRectanglesSitOnTheirHandles) {
    const Scenario s;
    const Frame f = Simulation(s).frame(123.0);
    for (int k = 1; k <= s.bench.bench_count; ++k) {
        const Rect& r = f.benches[static_cast<size_t>(k - 1)];
        const Vec2 front = f.handles[static_cast<size_t>(k - 1)].pos, rear = f.handles[static_cast<size_t>(k)].pos;
        EXPECT_NEAR(distance(r.centre, 0.5 * (front + rear)), 0.0, 1e-12);
        EXPECT_NEAR(r.half_length, 0.5 * s.bench.board_length(k), 1e-15);
        EXPECT_NEAR(r.half_width, 0.15, 1e-15);
        EXPECT_NEAR(dot(r.axis, normalized(front - rear)), 1.0, 1e-12);
    }
}

TEST(Chain, DeterministicFinalState) {
    // Same inputs, same bits (built with -ffp-contract=off): hash the final frame of a run.
    auto digest = [] {
        const Frame f = Simulation(Scenario{}).frame(412.0);
        double acc = 0.0;
        for (size_t i = 0; i < f.handles.size(); ++i)
            acc += (static_cast<double>(i) + 1.0) * (f.handles[i].pos.x() + 3.0 * f.handles[i].pos.y() + 7.0 * f.handles[i].speed);
        return acc;
    };
    EXPECT_EQ(digest(), digest());
}

TEST(Scenario, BadValuesAreRefusedWithTheirName) {
    auto expect_bad = [](Scenario s, const std::string& word) {
        try {
            validate(s);
            ADD_FAILURE() << "accepted: " << word;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << e.what();
        }
    };
    Scenario s;
    s.path.pitch = -1; expect_bad(s, "pitch");
    s = {}; s.path.pitch = std::nan(""); expect_bad(s, "pitch");
    s = {}; s.head_speed = 0; expect_bad(s, "head speed");
    s = {}; s.bench.body_length = -2; expect_bad(s, "body length");
    s = {}; s.bench.hole_offset = 1.1; expect_bad(s, "hole offset");
    s = {}; s.bench.bench_count = 0; expect_bad(s, "count");
    s = {}; s.path.start_turn = 0; expect_bad(s, "start turn");
    s = {}; s.path.pitch = 0.3; expect_bad(s, "pitch");  // not wider than a bench
    EXPECT_NO_THROW(validate(Scenario{}));
}

TEST(Scenario, TimesPastTheCentreAreRefused) {
    const Simulation sim(Scenario{});
    EXPECT_GT(sim.end_time(), 412.0);
    EXPECT_THROW(sim.frame(sim.end_time() + 1.0), InputError);
    EXPECT_THROW(sim.frame(std::nan("")), InputError);
    // The contest's dragon cannot follow the spiral that far: its motion ends 9.7 s earlier.
    EXPECT_LT(sim.valid_end(), sim.end_time() - 9.0);
    EXPECT_THROW(sim.frame(sim.end_time()), InputError);
    EXPECT_NO_THROW(sim.frame(sim.valid_end()));
}

// end_time() is the last moment the head is on the path, at any speed: frame(end_time()) works
// and the next representable time is refused. (At 180 m/s the division used to round one step
// past the centre: found by tests/fuzz/fuzz_scenario.) Short benches on a wide spiral, which
// the dragon can follow all the way to the centre.
TEST(Scenario, TheEndTimeItselfIsOnThePath) {
    for (double speed : {1e-6, 0.3, 1.0, 3.7, 180.0, 997.0, 1e6}) {
        for (double turn : {3.0, 16.0, 40.5}) {
            Scenario s;
            s.bench = {5, 0.8, 0.8, 0.2, 0.1};
            s.path.pitch = 2.0;
            s.head_speed = speed;
            s.path.start_turn = turn;
            const Simulation sim(s);
            const double end = sim.end_time();
            EXPECT_NO_THROW(sim.frame(end)) << "speed " << speed << ", start turn " << turn;
            EXPECT_THROW(sim.frame(std::nextafter(end, INFINITY) + 4.0 * (std::nextafter(end, INFINITY) - end)),
                         InputError)
                << "speed " << speed << ", start turn " << turn;
        }
    }
}

// The angles alone (what the proof of the untouched tail reads) are the whole solve's, bit for
// bit: far out and near the centre (where links reach round it), for long and short links.
TEST(Chain, AnglesAloneAreTheWholeSolvesAngles) {
    std::vector<double> theta;
    Frame f;
    int compared = 0;
    for (const double pitch : {0.32, 0.55, 1.7}) {
        for (const double body : {1.2, 2.2}) {
            BenchSpec spec;
            spec.body_length = body;
            const Spiral sp(pitch);
            // From far out down to a head a link's length from the centre.
            for (double head = -400.0; head < -0.5; head *= 0.93) {
                try {
                    solve_chain(sp, spec, head, 1.0, f);
                } catch (const SolverError&) {
                    continue;  // the chain runs off the spiral's outer end: no frame to compare
                }
                ASSERT_TRUE(solve_spiral_chain_angles(sp, spec, head, theta));
                ASSERT_EQ(theta.size(), f.handles.size());
                for (size_t k = 0; k < theta.size(); ++k) {
                    ASSERT_EQ(f.handles[k].place.piece, 0);
                    ASSERT_EQ(theta[k], f.handles[k].place.u) << "pitch " << pitch << ", head " << head << ", handle " << k;
                    ++compared;
                }
            }
        }
    }
    EXPECT_GT(compared, 50000);
    // Any other path: not solved, left as it was.
    Scenario turn;
    turn.path.kind = PathKind::turnaround;
    const Simulation tsim(turn);
    theta.assign(3, 7.0);
    EXPECT_FALSE(solve_spiral_chain_angles(tsim.path(), turn.bench, tsim.head_arc(0.0), theta));
    EXPECT_EQ(theta, std::vector<double>(3, 7.0));
}
