// The proof that the tail of the chain cannot touch anything over a stretch of the spiral
// (core/untouched_tail.hpp), checked from outside: every point of a board lies within the reach
// it claims; every pair with a bench past the watched ones stays apart at every sampled moment,
// every pair tested; and the contact search that leaves the tail out finds what the search
// watching every bench finds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <random>
#include <vector>

#include "core/untouched_tail.hpp"
#include "dragon/analyses.hpp"
#include "dragon/collision.hpp"
#include "dragon/path.hpp"
#include "dragon/portable_math.hpp"

using namespace dragon;

namespace {

// The angle psi of point x unwrapped next to the spiral's angle theta at point `near` (both
// on the same side of the centre, well within half a turn of each other).
double unwrapped_angle(const Spiral& sp, const Vec2& near, double theta, const Vec2& x) {
    // The spiral's angle grows counter-clockwise when a point a little farther out along it
    // lies counter-clockwise of this one.
    const double sense = cross(near, sp.at({0, theta + 1e-3}).pos) > 0.0 ? 1.0 : -1.0;
    return theta + sense * dragon::math::atan2(cross(near, x), dot(near, x));
}

BenchSpec wide_short() {
    BenchSpec s;
    s.width = 0.6;
    s.head_length = 1.5;
    s.body_length = 1.2;
    s.hole_offset = 0.1;
    return s;
}

BenchSpec long_ends() {
    BenchSpec s;
    s.body_length = 3.0;
    s.head_length = 4.0;
    s.hole_offset = 0.6;
    return s;
}

// A lower bound on the separation of the pairs (i, j), j >= i + 2, with j past the first
// `watched` benches, positive exactly when none of them touches: every such pair, no broad
// phase; a pair whose bounding circles are apart counts by their distance (the exact
// separation of the other pairs is what costs: 25 000 a frame, minutes under the sanitizers).
double tail_clearance(const Frame& f, int watched) {
    double best = std::numeric_limits<double>::infinity();
    const int n = static_cast<int>(f.benches.size());
    for (int j = std::max(watched + 1, 3); j <= n; ++j) {
        const Rect& b = f.benches[static_cast<size_t>(j - 1)];
        for (int i = 1; i + 2 <= j; ++i) {
            const Rect& a = f.benches[static_cast<size_t>(i - 1)];
            const double circles = (a.centre - b.centre).norm() - half_diagonal(a) - half_diagonal(b);
            best = std::min(best, circles > 0.0 ? circles : separation(a, b).distance);
        }
    }
    return best;
}

// The search with nothing left out, to check the shortcut against.
ContactSearchOptions watch_every_bench() {
    ContactSearchOptions o;
    o.skip_untouched_tail = false;
    return o;
}

}  // namespace

TEST(UntouchedTail, EveryBoardPointLiesWithinItsBenchsReach) {
    struct Case {
        BenchSpec spec;
        std::vector<double> pitches;
    };
    const std::vector<Case> cases = {{BenchSpec{}, {0.32, 0.55, 1.7, 4.0}},
                                     {wide_short(), {0.65, 1.0, 3.0}},
                                     {long_ends(), {0.35, 0.55, 2.0}}};
    int checked = 0;
    double fullest_in = 0.0, fullest_out = 0.0;  // observed over bound, largest
    for (const Case& c : cases) {
        for (const double pitch : c.pitches) {
            const Spiral sp(pitch);
            const double b = sp.b();
            for (double radius = 0.3; radius < 60.0; radius *= 1.07) {
                for (const int bench : {1, 2}) {
                    const double theta = radius / b;
                    const Located front = sp.at({0, theta});
                    const std::optional<Located> rear = sp.behind(front, c.spec.link_length(bench));
                    ASSERT_TRUE(rear.has_value());
                    const std::optional<BenchReach> reach =
                        bench_reach(b, c.spec, bench, theta, rear->place.u, rear->place.u - theta);
                    if (!reach) {
                        // Refused only near the centre, within a few boards' widths.
                        EXPECT_LT(radius, 2.0 * c.spec.link_length(bench)) << "pitch " << pitch;
                        continue;
                    }
                    ++checked;
                    const Rect r = bench_rect(c.spec, bench, front.pos, rear->pos);
                    double low = INFINITY, high = -INFINITY;
                    for (int u = -40; u <= 40; ++u) {
                        for (int v = -8; v <= 8; ++v) {
                            const Vec2 x = r.centre + (r.half_length * u / 40.0) * r.axis +
                                           (r.half_width * v / 8.0) * perp(r.axis);
                            const double psi = unwrapped_angle(sp, front.pos, theta, x);
                            const double offset = norm(x) - b * psi;
                            low = std::min(low, offset);
                            high = std::max(high, offset);
                            ASSERT_GE(psi, theta - reach->angle) << "pitch " << pitch << ", radius " << radius;
                            ASSERT_LE(psi, rear->place.u + reach->angle) << "pitch " << pitch << ", radius " << radius;
                        }
                    }
                    ASSERT_GE(low, -reach->in) << "pitch " << pitch << ", radius " << radius << ", bench " << bench;
                    ASSERT_LE(high, reach->out) << "pitch " << pitch << ", radius " << radius << ", bench " << bench;
                    fullest_in = std::max(fullest_in, -low / reach->in);
                    fullest_out = std::max(fullest_out, high / reach->out);
                }
            }
        }
    }
    EXPECT_GT(checked, 500);
    // Not loose either: somewhere (far out) a board reaches nearly all of its bound.
    EXPECT_GT(fullest_in, 0.95);
    EXPECT_GT(fullest_out, 0.95);
}

// Cut into stretches of 10 m of head travel as the search cuts them, every run below: at a
// nine moments of each stretch, every pair with a bench past the watched ones is apart.
TEST(UntouchedTail, TheTailStaysApartOverEveryStretch) {
    struct Case {
        const char* name;
        Scenario s;
        bool to_boundary;
    };
    std::vector<Case> cases;
    cases.push_back({"contest, to the first contact", Scenario{}, false});
    Scenario q3;
    q3.path.pitch = 0.4503;
    cases.push_back({"pitch 0.4503, to the boundary", q3, true});
    Scenario window;
    window.path.pitch = 0.44;  // a contact window opens and closes on the way in
    cases.push_back({"pitch 0.44, to the boundary", window, true});
    Scenario wide;
    wide.bench = wide_short();
    wide.path.pitch = 0.7;
    wide.bench.bench_count = 300;
    cases.push_back({"wide short benches", wide, false});
    int stretches = 0, proved = 0;
    Frame f;
    for (const Case& c : cases) {
        const Simulation sim(c.s);
        double end = c.to_boundary ? boundary_time(sim) : sim.valid_end();
        end = std::min(end, sim.valid_end());
        if (!c.to_boundary) {
            if (const auto hit = first_contact(sim, 0.0, end, watch_every_bench())) end = hit->time;
        }
        const int n = c.s.bench.bench_count;
        for (double a = 0.0; a < end; a += 10.0) {
            const double z = std::min(end, a + 10.0);
            const int watched = benches_that_may_touch(dynamic_cast<const Spiral&>(sim.path()), c.s.bench, sim.frame(a),
                                                       sim.frame(z));
            ++stretches;
            if (watched < n / 4) ++proved;
            if (watched == n) continue;
            for (int k = 0; k <= 8; ++k) {
                const double t = k == 8 ? z : a + (z - a) * k / 8.0;
                sim.frame_into(t, f);
                ASSERT_GT(tail_clearance(f, watched), 0.0)
                    << c.name << ": t = " << t << " in [" << a << ", " << z << "], " << watched << " watched";
            }
        }
    }
    // The proof is worth having: most stretches leave most of the chain out.
    EXPECT_GT(proved, stretches * 3 / 4) << proved << " of " << stretches;
}

// The search with the tail left out (the default) and watching every bench: the same contact,
// or none, on the contest's runs, near the minimum pitch, through a contact window, for a
// fast head, and for random benches and pitches.
TEST(UntouchedTail, TheSearchFindsWhatWatchingEveryBenchFinds) {
    std::vector<std::pair<Scenario, double>> runs;  // scenario, end of the search (< 0: valid end)
    runs.push_back({Scenario{}, -1.0});
    for (const double p : {0.44, 0.4503, 0.4504, 0.46}) {
        Scenario s;
        s.path.pitch = p;
        runs.push_back({s, 1.0});  // 1: to the boundary
    }
    Scenario fast;
    fast.path.pitch = 0.6;
    fast.head_speed = 3.0;
    runs.push_back({fast, -1.0});
    std::mt19937 rng(20261123);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    while (runs.size() < 14) {
        Scenario s;
        s.bench.bench_count = 30 + static_cast<int>(270 * unit(rng));
        s.bench.width = 0.2 + 0.3 * unit(rng);
        s.bench.body_length = 1.2 + 1.8 * unit(rng);
        s.bench.head_length = s.bench.body_length + 1.5 * unit(rng);
        s.bench.hole_offset = 0.1 + 0.25 * unit(rng);
        s.path.pitch = s.bench.width + 0.02 + 0.5 * unit(rng);
        try {
            const Simulation probe(s);
            probe.frame(0.0);
        } catch (const InputError&) {
            continue;  // a chain that does not fit on the spiral
        }
        runs.push_back({s, -1.0});
    }
    int contacts = 0;
    for (const auto& [s, end_kind] : runs) {
        const Simulation sim(s);
        const double end = end_kind < 0.0 ? sim.valid_end() : std::min(sim.valid_end(), boundary_time(sim));
        const auto quick = first_contact(sim, 0.0, end);
        const auto every = first_contact(sim, 0.0, end, watch_every_bench());
        const std::string name = "pitch " + std::to_string(s.path.pitch) + ", " + std::to_string(s.bench.bench_count) +
                                 " benches of width " + std::to_string(s.bench.width);
        ASSERT_EQ(quick.has_value(), every.has_value()) << name;
        if (!quick) continue;
        ++contacts;
        EXPECT_EQ(quick->bench_a, every->bench_a) << name;
        EXPECT_EQ(quick->bench_b, every->bench_b) << name;
        EXPECT_NEAR(quick->time, every->time, 2.0 * std::max(quick->tolerance, every->tolerance)) << name;
        EXPECT_EQ(quick->frame.benches.size(), static_cast<size_t>(s.bench.bench_count)) << name;  // the whole chain
    }
    EXPECT_GE(contacts, 6);
}

namespace {

// The proof as its comment states it, written plainly: every libm call made, every partner
// found by a full bisection. The library's version skips the calls whose outcome a cheaper bound
// already settles and searches from a hint; it must watch exactly as many benches.
std::optional<BenchReach> plain_reach(double b, const BenchSpec& spec, int bench, double front_last, double rear_last,
                                      double span_first) {
    const double d = spec.link_length(bench), o = spec.hole_offset, hw = 0.5 * spec.width;
    const double rho = b * front_last, corner = dragon::math::hypot(o, hw);
    if (!(rho > 0.5 * d)) return std::nullopt;
    const double seg = std::sqrt(rho * rho - 0.25 * d * d);
    if (!(seg > 2.0 * corner)) return std::nullopt;
    const double line = seg - o, near = seg - corner;
    const double curv = 1.0 / line + b / (line * line);
    const double grad = std::sqrt(1.0 + (b / near) * (b / near));
    const double h = rho * (b * rear_last) * dragon::math::sin(span_first) / d;
    double in = curv * d * d / 8.0, out = curv * o * (d + o) / 2.0;
    if (!(h > 2.0 * b)) in = out = std::max(in, out);
    const double widen = 1.0 + 1e-9;
    return BenchReach{(in + grad * hw) * widen, (out + grad * hw) * widen, dragon::math::asin(corner / seg) * widen};
}

int plain_benches_that_may_touch(const Spiral& spiral, const BenchSpec& spec, const Frame& first, const Frame& last) {
    constexpr double slack = 1e-9;
    const int n = spec.bench_count;
    const size_t handles = static_cast<size_t>(n) + 1;
    if (first.handles.size() != handles || last.handles.size() != handles || !(first.time <= last.time)) return n;
    std::vector<double> tf, tl;
    for (size_t k = 0; k < handles; ++k) {
        if (first.handles[k].place.piece != 0 || last.handles[k].place.piece != 0) return n;
        tf.push_back(first.handles[k].place.u);
        tl.push_back(last.handles[k].place.u);
    }
    for (size_t k = 0; k < handles; ++k) {
        if (!(tf[k] >= tl[k])) return n;
        if (k + 1 == handles) break;
        const double span_last = tl[k + 1] - tl[k], span_first = tf[k + 1] - tf[k];
        if (!(span_last > 0.0 && span_last < 0.5 * std::numbers::pi && tl[k] > dragon::math::tan(0.5 * span_last))) return n;
        if (!(span_first > 0.0 && span_first <= span_last * (1.0 + slack))) return n;
    }
    const double b = spiral.b(), pitch = spiral.pitch();
    std::vector<BenchReach> reach(handles);
    for (size_t k = 1; k <= static_cast<size_t>(n); ++k) {
        const auto r = plain_reach(b, spec, static_cast<int>(k), tl[k - 1], tl[k], tf[k] - tf[k - 1]);
        if (!r) return n;
        reach[k] = *r;
    }
    std::vector<double> in_from(handles + 1, 0.0), angle_from(handles + 1, 0.0);
    for (size_t k = handles - 1; k >= 1; --k) {
        in_from[k] = std::max(in_from[k + 1], reach[k].in);
        angle_from[k] = std::max(angle_from[k + 1], reach[k].angle);
    }
    int watched = std::min(n, 2);
    for (int i = n - 2; i >= 1; --i) {
        const size_t ki = static_cast<size_t>(i), j0 = ki + 2;
        const BenchReach& ri = reach[ki];
        const double turns = (ri.out + in_from[j0]) / pitch;
        if (turns > 8) return n;
        for (int m = 0; m <= static_cast<int>(turns); ++m) {
            const double shift = 2.0 * std::numbers::pi * m;
            const double widest = ri.angle + angle_from[j0] + slack * (1.0 + tl.back());
            const size_t top = static_cast<size_t>(std::upper_bound(tf.begin(), tf.end(), tf[ki] + shift + widest) - tf.begin());
            const size_t j_hi = std::min(top, static_cast<size_t>(n));
            const size_t j_lo = std::max(
                j0, static_cast<size_t>(std::lower_bound(tl.begin(), tl.end(), tl[ki - 1] + shift - widest) - tl.begin()));
            for (size_t j = j_hi; j >= j_lo && static_cast<int>(j) > watched; --j) {
                const double apart = ri.angle + reach[j].angle, s = slack * (1.0 + tl[j]);
                const bool offsets_meet = pitch * m <= ri.out + reach[j].in;
                const bool behind = tf[j - 1] - tf[ki] > shift + apart + s;
                const bool ahead = tl[j] - tl[ki - 1] < shift - apart - s;
                if (offsets_meet && !behind && !ahead) {
                    watched = static_cast<int>(j);
                    break;
                }
            }
        }
    }
    return watched;
}

}  // namespace

// The same count as the plain proof, over every stretch of runs to the boundary and beyond on the
// contest's chain and on random ones (wide and narrow boards, near and far from the centre), and
// the same reach for every bench of them (the proof's and the public bench_reach's).
TEST(UntouchedTail, TheShortCutsWatchWhatThePlainProofWatches) {
    std::mt19937 rng(20261125);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<Scenario> runs(1);
    for (const double p : {0.32, 0.44, 0.55, 1.2}) {
        Scenario s;
        s.path.pitch = p;
        runs.push_back(s);
    }
    while (runs.size() < 16) {
        Scenario s;
        s.bench.bench_count = 20 + static_cast<int>(250 * unit(rng));
        s.bench.width = 0.15 + 0.4 * unit(rng);
        s.bench.body_length = 1.0 + 2.0 * unit(rng);
        s.bench.head_length = s.bench.body_length + 1.5 * unit(rng);
        s.bench.hole_offset = 0.1 + 0.25 * unit(rng);
        s.path.pitch = s.bench.width + 0.02 + 0.6 * unit(rng);
        try {
            Simulation(s).frame(0.0);
        } catch (const InputError&) {
            continue;
        }
        runs.push_back(s);
    }
    int stretches = 0, partial = 0, reaches = 0;
    for (const Scenario& s : runs) {
        const Simulation sim(s);
        const auto& sp = dynamic_cast<const Spiral&>(sim.path());
        const double end = sim.valid_end();
        for (double a = 0.0; a < end; a += 3.7) {
            const Frame first = sim.frame(a), last = sim.frame(std::min(end, a + 10.0));
            const int plain = plain_benches_that_may_touch(sp, s.bench, first, last);
            ASSERT_EQ(benches_that_may_touch(sp, s.bench, first, last), plain) << "pitch " << s.path.pitch << ", t = " << a;
            ASSERT_EQ(benches_that_may_touch(sp, s.bench, chain_angles(first), chain_angles(last)), plain);
            ++stretches;
            if (plain < s.bench.bench_count) ++partial;
            for (size_t k = 1; k < first.handles.size(); ++k) {
                const double tf0 = first.handles[k - 1].place.u, tf1 = first.handles[k].place.u;
                const double tl0 = last.handles[k - 1].place.u, tl1 = last.handles[k].place.u;
                const auto mine = bench_reach(sp.b(), s.bench, static_cast<int>(k), tl0, tl1, tf1 - tf0);
                const auto ref = plain_reach(sp.b(), s.bench, static_cast<int>(k), tl0, tl1, tf1 - tf0);
                ASSERT_EQ(mine.has_value(), ref.has_value());
                if (!mine) continue;
                ++reaches;
                ASSERT_EQ(mine->in, ref->in);
                ASSERT_EQ(mine->out, ref->out);
                ASSERT_EQ(mine->angle, ref->angle);
            }
        }
    }
    EXPECT_GT(stretches, 200);
    EXPECT_GT(partial, stretches / 2);  // the proof mostly succeeds, so its every branch is taken
    EXPECT_GT(reaches, 100000);
}

TEST(UntouchedTail, ProvesNothingItCannot) {
    const Scenario contest;
    const Simulation sim(contest);
    const auto& sp = dynamic_cast<const Spiral&>(sim.path());
    const int n = contest.bench.bench_count;
    // Backwards in time, or frames of another chain.
    EXPECT_EQ(benches_that_may_touch(sp, contest.bench, sim.frame(20.0), sim.frame(10.0)), n);
    EXPECT_EQ(benches_that_may_touch(sp, contest.bench, sim.leading(50).frame(10.0), sim.frame(20.0)), n);
    // The head near the centre, where the head bench's board wraps round it.
    const double end = sim.valid_end();
    EXPECT_EQ(benches_that_may_touch(sp, contest.bench, sim.frame(end - 1.0), sim.frame(end)), n);
    // The turnaround path: the frames leave the coil-in spiral.
    Scenario turn;
    turn.path.kind = PathKind::turnaround;
    const Simulation tsim(turn);
    const Spiral coil(turn.path.turn_pitch);
    EXPECT_EQ(benches_that_may_touch(coil, turn.bench, tsim.frame(-5.0), tsim.frame(5.0)), n);
    // Far out the tail is proved untouched whole; a short chain keeps what it has.
    EXPECT_EQ(benches_that_may_touch(sp, contest.bench, sim.frame(0.0), sim.frame(10.0)), 2);
    Scenario one = contest;
    one.bench.bench_count = 1;
    const Simulation osim(one);
    EXPECT_EQ(benches_that_may_touch(sp, one.bench, osim.frame(0.0), osim.frame(10.0)), 1);
}

TEST(UntouchedTail, LeadingBenchesAreTheWholeChainsFirstOnes) {
    const Simulation sim(Scenario{});
    const Simulation lead = sim.leading(30);
    EXPECT_EQ(lead.solved_benches(), 30);
    EXPECT_EQ(sim.solved_benches(), 223);
    EXPECT_EQ(sim.leading(0).solved_benches(), 1);
    EXPECT_EQ(sim.leading(1000).solved_benches(), 223);
    for (const double t : {0.0, 100.0, 400.0}) {
        const Frame all = sim.frame(t), part = lead.frame(t);
        ASSERT_EQ(part.handles.size(), 31u);
        ASSERT_EQ(part.benches.size(), 30u);
        for (size_t k = 0; k < part.handles.size(); ++k) {
            EXPECT_EQ(part.handles[k].pos.x(), all.handles[k].pos.x());
            EXPECT_EQ(part.handles[k].pos.y(), all.handles[k].pos.y());
            EXPECT_EQ(part.handles[k].speed, all.handles[k].speed);
        }
    }
    // Its valid range is the whole chain's.
    EXPECT_EQ(lead.valid_end(), sim.valid_end());
    EXPECT_THROW(lead.frame(sim.valid_end() + 1.0), InputError);
}

// On the turnaround's way in, before the head reaches the turn, the whole chain coils in along
// the coil-in spiral as on the plain spiral (Path::coil_in_spiral): the search leaves out the
// tail there, and finds what watching every bench finds. At turn pitches below the contest's
// minimum pitch the dragon touches on the way in; at 1.7 m it does not, nor later in the window.
TEST(UntouchedTail, TheTurnaroundsWayInLeavesOutTheTail) {
    Scenario turn;
    turn.path.kind = PathKind::turnaround;
    const Simulation tsim(turn);
    const Spiral* coil = tsim.path().coil_in_spiral(tsim.frame(-20.0).handles[0].place);
    ASSERT_NE(coil, nullptr);
    EXPECT_LT(benches_that_may_touch(*coil, turn.bench, tsim.frame(-20.0), tsim.frame(-10.0)), 10);
    EXPECT_EQ(tsim.path().coil_in_spiral(tsim.frame(5.0).handles[0].place), nullptr);  // the head in the turn
    int contacts = 0;
    for (const double pitch : {0.42, 0.44, 1.7}) {
        Scenario s = turn;
        s.path.turn_pitch = pitch;
        const Simulation sim(s);
        const double from = sim.valid_range().from_travel;
        const double lo = std::max(from, -150.0), hi = std::min(sim.valid_range().to_travel, 100.0);
        const auto quick = first_contact_travel(sim, lo, hi);
        const auto every = first_contact_travel(sim, lo, hi, watch_every_bench());
        ASSERT_EQ(quick.has_value(), every.has_value()) << "turn pitch " << pitch;
        if (!quick) continue;
        ++contacts;
        EXPECT_EQ(quick->bench_a, every->bench_a) << "turn pitch " << pitch;
        EXPECT_EQ(quick->bench_b, every->bench_b) << "turn pitch " << pitch;
        EXPECT_NEAR(quick->travel, every->travel, 2.0 * std::max(quick->travel_tolerance, every->travel_tolerance));
        EXPECT_LT(quick->travel, 0.0) << "turn pitch " << pitch;  // on the way in
    }
    EXPECT_EQ(contacts, 2);
}
