// Q2 and Q3: the published values, and that the reported first contact really is first.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/contact_step.hpp"
#include "dragon/analyses.hpp"
#include "dragon/collision.hpp"
#include "dragon/constants.hpp"
#include "dragon/executor.hpp"

using namespace dragon;

TEST(Q2, TerminationTimeMatchesPublished) {
    const Simulation sim(Scenario{});
    const auto c = first_contact(sim, 0.0, sim.valid_end());
    ASSERT_TRUE(c.has_value());
    EXPECT_NEAR(c->time, 412.4738, 5e-5);  // PROBLEM.md: about 412.4738 s
    // At the moment the pair touches: separation zero to the bisection's tolerance.
    const Clearance at = clearance(c->frame);
    EXPECT_LE(at.distance, 0.0);
    EXPECT_GT(at.distance, -1e-8);
    const Clearance before = clearance(sim.frame(c->time - 1e-8));
    EXPECT_GT(before.distance, 0.0);
    EXPECT_EQ(c->bench_a, 1);  // the head bench hits the next turn out
}

TEST(Q2, NoContactBeforeTheReportedOne) {
    const Simulation sim(Scenario{});
    const auto c = first_contact(sim, 0.0, sim.valid_end());
    ASSERT_TRUE(c.has_value());
    // A dense scan: every 0.05 s over the whole run, then every 1e-4 s over the last second.
    for (double t = 0.0; t < c->time - 1.0; t += 0.05)
        ASSERT_GT(clearance(sim.frame(t)).distance, 0.0) << "t " << t;
    for (double t = c->time - 1.0; t < c->time - 1e-9; t += 1e-4)
        ASSERT_GT(clearance(sim.frame(t)).distance, 0.0) << "t " << t;
}

TEST(Q2, OtherScenariosToo) {
    // A tighter pitch and a faster head: the contact is still first and exact.
    Scenario s;
    s.path.pitch = 0.5;
    s.head_speed = 2.0;
    const Simulation sim(s);
    const auto c = first_contact(sim, 0.0, sim.valid_end());
    ASSERT_TRUE(c.has_value());
    EXPECT_LE(clearance(c->frame).distance, 0.0);
    EXPECT_GT(clearance(sim.frame(c->time - 2e-9)).distance, 0.0);
    for (double t = 0.0; t < c->time - 0.5; t += 0.25) ASSERT_GT(clearance(sim.frame(t)).distance, 0.0);
}

TEST(Q2, ScalesWithTheHeadSpeed) {
    // The chain at head speed v is the chain at 1 m/s with time divided by v, so the contact
    // time times v must not depend on v. A slow dragon once crept in 1 s steps (hours at
    // 1e-6 m/s); a fast one must still be resolved to the metres of head travel.
    const Simulation ref_sim(Scenario{});
    const auto ref = first_contact(ref_sim, 0.0, ref_sim.valid_end());
    ASSERT_TRUE(ref.has_value());
    for (double v : {1e-6, 1e-3, 1e3, 1e6}) {
        Scenario s;
        s.head_speed = v;
        const Simulation sim(s);
        const auto c = first_contact(sim, 0.0, sim.valid_end());
        ASSERT_TRUE(c.has_value()) << "speed " << v;
        EXPECT_EQ(c->bench_a, ref->bench_a) << "speed " << v;
        EXPECT_EQ(c->bench_b, ref->bench_b) << "speed " << v;
        // Head travel to the contact agrees to the coarser of the two runs' resolutions.
        EXPECT_NEAR(c->time * v, ref->time, 2.0 * std::max(c->tolerance * v, ref->tolerance)) << "speed " << v;
        EXPECT_LE(c->tolerance * v, std::max(1e-10, 4.0 * (std::nextafter(c->time, INFINITY) - c->time) * v));
        EXPECT_LT(c->steps, 2 * ref->steps) << "speed " << v;
    }
}

// The stepper's claim, checked from outside: inside every interval it declared contact-free by
// its bounds, without looking, the benches are apart. At least sixteen samples per step and one
// per 0.05 m of head travel, for the contest run, a pitch just above the minimum (clearance
// dipping to near zero and recovering), a pitch with a contact window that opens and closes
// (a step over it would be caught here), a fast head, and the turnaround path.
TEST(Q2, EveryStepDeclaredSafeIsSafe) {
    struct Case {
        const char* name;
        Scenario s;
        double from, to;
    };
    std::vector<Case> cases;
    cases.push_back({"contest", Scenario{}, 0.0, -1.0});
    Scenario tight;
    tight.path.pitch = 0.4504;  // just above the minimum pitch: grazes on the way in
    cases.push_back({"pitch 0.4504", tight, 0.0, -1.0});
    Scenario window;
    window.path.pitch = 0.44;  // benches 1 and 19 touch over 181.2..~189 s, part, touch again at 197.5 s
    cases.push_back({"pitch 0.44", window, 0.0, -1.0});
    Scenario fast;
    fast.head_speed = 3.0;
    fast.path.pitch = 0.6;
    cases.push_back({"pitch 0.6, 3 m/s", fast, 0.0, -1.0});
    Scenario turn;
    turn.path.kind = PathKind::turnaround;
    cases.push_back({"turnaround", turn, -100.0, 100.0});
    Scenario turn_tight = turn;
    turn_tight.path.turn_pitch = 1.0;  // the head meets bench 16 on the S-curve's first arc
    cases.push_back({"turnaround, turn pitch 1.0", turn_tight, -20.0, 20.0});
    for (const Case& c : cases) {
        const Simulation sim(c.s);
        const double to = c.to < 0.0 ? sim.valid_end() : c.to;
        int steps = 0;
        double covered = c.from, longest = 0.0;
        Frame f;
        const auto contact = first_contact(sim, c.from, to, {.on_step = [&](double a, double b) {
            ++steps;
            EXPECT_DOUBLE_EQ(a, covered) << c.name << ": steps leave a gap";
            covered = b;
            longest = std::max(longest, b - a);
            const int samples = std::max(16, static_cast<int>(std::ceil((b - a) * c.s.head_speed / 0.05)));
            for (int k = 1; k <= samples; ++k) {
                const double t = a + (b - a) * k / samples;
                sim.frame_into(t, f);
                const Clearance cl = clearance(f);
                ASSERT_GT(cl.distance, 0.0) << c.name << ": benches " << cl.bench_a << " and " << cl.bench_b
                                            << " touch at t = " << t << " inside the step [" << a << ", " << b << "]";
            }
        }});
        EXPECT_GT(steps, 10) << c.name;
        // A contact ends the steps just before it; no contact: they cover the whole range.
        if (contact) EXPECT_LE(covered, contact->time) << c.name;
        else EXPECT_DOUBLE_EQ(covered, to) << c.name;
        EXPECT_GT(longest, 0.1) << c.name;  // not crawling either
    }
}

// The search cut into chunks on several threads finds what one thread finds: the same pair, the
// same moment to the tolerance, also where a contact window opens and closes (pitch 0.44) and
// where there is no contact at all (a wide pitch).
TEST(Q2, ThreadsDoNotChangeTheAnswer) {
    std::vector<Scenario> scenarios(4);
    scenarios[1].path.pitch = 0.44;
    scenarios[2].path.pitch = 0.5;
    scenarios[2].head_speed = 2.0;
    scenarios[3].path.pitch = 0.9;
    InlineExecutor inline_executor;
    ThreadPool two(2), three(3);
    for (const Scenario& s : scenarios) {
        const Simulation sim(s);
        const auto one = first_contact(sim, 0.0, sim.valid_end(), {.on_step = {}, .executor = &inline_executor});
        for (ThreadPool* pool : {&two, &three}) {
            const int threads = pool->workers();
            const auto many = first_contact(sim, 0.0, sim.valid_end(), {.on_step = {}, .executor = pool});
            ASSERT_EQ(one.has_value(), many.has_value()) << "pitch " << s.path.pitch << ", " << threads << " threads";
            if (!one) continue;
            EXPECT_EQ(one->bench_a, many->bench_a);
            EXPECT_EQ(one->bench_b, many->bench_b);
            EXPECT_NEAR(one->time, many->time, one->tolerance + many->tolerance) << "pitch " << s.path.pitch;
            // Deterministic for a given thread count.
            const auto again = first_contact(sim, 0.0, sim.valid_end(), {.on_step = {}, .executor = pool});
            EXPECT_EQ(again->time, many->time);
            EXPECT_EQ(again->steps, many->steps);
        }
    }
}

TEST(Q3, MinimumPitchMatchesPublished) {
    const MinPitch m = min_pitch(Scenario{}, 0.40, 0.50);
    EXPECT_NEAR(m.pitch, 0.4503, 5e-5);  // PROBLEM.md: about 0.4503
    // At it the run reaches the boundary; the tolerance below it, the run collides.
    EXPECT_FALSE(contact_before_boundary(Scenario{}, m.pitch).has_value());
    EXPECT_FALSE(contact_before_boundary(Scenario{}, m.pitch + 1e-7).has_value());
    EXPECT_TRUE(contact_before_boundary(Scenario{}, m.pitch - 1.001 * tol::pitch).has_value());
    EXPECT_TRUE(contact_before_boundary(Scenario{}, m.pitch - 1e-7).has_value());
    // The intervals tile the searched range and alternate.
    ASSERT_FALSE(m.intervals.empty());
    EXPECT_DOUBLE_EQ(m.intervals.front().lo, 0.40);
    EXPECT_DOUBLE_EQ(m.intervals.back().hi, 0.50);
    for (size_t k = 1; k < m.intervals.size(); ++k) {
        EXPECT_DOUBLE_EQ(m.intervals[k].lo, m.intervals[k - 1].hi);
        EXPECT_NE(m.intervals[k].feasible, m.intervals[k - 1].feasible);
    }
}

// The search's grid is 2.5 mm; a scan at 1 mm over the whole default range finds the same
// feasible and infeasible pitches the search reported: no window slipped between grid points.
// Other dragons: the cut is exact to the tolerance there too, whichever way it was narrowed
// (regula falsi on the closing pair's closest approach, or k-section where that does not apply).
TEST(Q3, OtherScenariosCutToTheTolerance) {
    Scenario wide;
    wide.bench.width = 0.4;
    Scenario ring;
    ring.path.turn_radius = 3.5;
    Scenario short_chain;
    short_chain.bench.bench_count = 60;
    for (const Scenario& s : {wide, ring, short_chain}) {
        const MinPitch m = min_pitch(s, s.bench.width + 0.05, 0.6);
        ASSERT_TRUE(std::isfinite(m.pitch));
        for (size_t k = 1; k < m.intervals.size(); ++k) {
            const double cut = m.intervals[k].lo;
            // A cut is reported at its feasible side; a tolerance across it, the run collides.
            const bool feasible_above = m.intervals[k].feasible;
            EXPECT_FALSE(contact_before_boundary(s, cut).has_value()) << "cut " << cut;
            const double other = feasible_above ? cut - 1.001 * tol::pitch : cut + 1.001 * tol::pitch;
            EXPECT_TRUE(contact_before_boundary(s, other).has_value()) << "cut " << cut;
        }
    }
}

TEST(Q3, AFinerScanAgreesWithTheReportedIntervals) {
    const MinPitch m = min_pitch(Scenario{}, 0.35, 0.55);
    for (int k = 0; k <= 200; ++k) {
        const double p = 0.35 + 1e-3 * k;
        bool reported = false;
        for (const PitchInterval& iv : m.intervals)
            if (p >= iv.lo && p <= iv.hi) reported = iv.feasible;
        if (std::abs(p - m.pitch) < 1e-6) continue;  // on the cut itself
        EXPECT_EQ(!contact_before_boundary(Scenario{}, p).has_value(), reported) << "pitch " << p;
    }
}

// The same pitches are run on one worker or many (the k-section's points are fixed, not one per
// worker), so every number of the answer is the same bits; the jam's change (turning space 1.2
// m, 0.89..0.90 m: feasibility changes from a jam, which only the k-section narrows) included.
TEST(Q3, TheAnswerDoesNotDependOnTheExecutor) {
    struct Case {
        Scenario s;
        double lo, hi, grid;
    };
    Scenario ring;
    ring.path.turn_radius = 1.2;
    Scenario late_start;
    late_start.path.start_turn = 10;
    const std::vector<Case> cases = {{Scenario{}, 0.35, 0.55, kDefaultPitchGrid},
                                     {ring, 0.85, 0.95, 0.01},
                                     {late_start, 0.451, 0.55, kDefaultPitchGrid}};
    InlineExecutor serial;
    ThreadPool two(2), three(3), seven(7);
    for (const Case& c : cases) {
        MinPitchOptions o;
        o.grid = c.grid;
        o.executor = &serial;
        const MinPitch want = min_pitch(c.s, c.lo, c.hi, o);
        for (Executor* ex : std::initializer_list<Executor*>{&two, &three, &seven}) {
            o.executor = ex;
            const MinPitch got = min_pitch(c.s, c.lo, c.hi, o);
            const std::string where = "range " + std::to_string(c.lo) + ".." + std::to_string(c.hi) + ", " +
                                      std::to_string(ex->workers()) + " workers";
            EXPECT_TRUE(std::isnan(want.pitch) ? std::isnan(got.pitch) : want.pitch == got.pitch) << where;
            EXPECT_EQ(want.below_range, got.below_range) << where;
            EXPECT_EQ(want.grid, got.grid) << where;
            ASSERT_EQ(want.intervals.size(), got.intervals.size()) << where;
            for (size_t k = 0; k < want.intervals.size(); ++k) {
                EXPECT_EQ(want.intervals[k].lo, got.intervals[k].lo) << where;
                EXPECT_EQ(want.intervals[k].hi, got.intervals[k].hi) << where;
                EXPECT_EQ(want.intervals[k].feasible, got.intervals[k].feasible) << where;
            }
            ASSERT_EQ(want.jam.has_value(), got.jam.has_value()) << where;
            if (want.jam) {
                EXPECT_EQ(want.jam->pitch, got.jam->pitch) << where;
                EXPECT_EQ(want.jam->jam.time, got.jam->jam.time) << where;
            }
        }
    }
}

// A range whose low end starts the head inside the turning space is refused as the range's, the
// same error on one worker or many; the range may start anywhere above that pitch, and the
// answer says how far down a lower start may go.
TEST(Q3, ARangeStartingInsideTheTurningSpaceIsRefusedAsSuch) {
    Scenario s;
    s.path.start_turn = 10;  // the head starts at radius 10 p: inside 4.5 m for p <= 0.45
    InlineExecutor serial;
    ThreadPool four(4);
    for (Executor* ex : std::initializer_list<Executor*>{&serial, &four}) {
        MinPitchOptions o;
        o.executor = ex;
        try {
            min_pitch(s, 0.35, 0.55, o);
            ADD_FAILURE() << "not refused";
        } catch (const InputError& e) {
            EXPECT_EQ(e.field(), "pitch search range start");
            EXPECT_EQ(e.value(), "0.35");
        }
        EXPECT_THROW(min_pitch(s, 0.45, 0.55, o), InputError);
        const MinPitch m = min_pitch(s, 0.45 + 1e-6, 0.55, o);
        EXPECT_TRUE(m.below_range);
        EXPECT_TRUE(m.lowest_is_start);
        EXPECT_DOUBLE_EQ(m.lowest, 0.45);
    }
}

TEST(Q2, AWidePitchCoilsInWithoutContact) {
    // At pitch 0.7 m the dragon coils in untouched as far as it can follow the spiral (its valid
    // motion ends before the centre): the search says so, and a scan agrees.
    Scenario s;
    s.path.pitch = 0.7;
    const Simulation sim(s);
    EXPECT_FALSE(first_contact(sim, 0.0, sim.valid_end()).has_value());
    for (double t = 0.0; t <= sim.valid_end(); t += 0.5) ASSERT_GT(clearance(sim.frame(t)).distance, 0.0) << t;
}

TEST(Q2, AProbeBracketNeverPassesOverAnotherPairsContact) {
    // Pitch 0.5 m at 2 m/s, searched from 159.06 s: near 166.96 s a pair 2 mm apart and closing
    // slowly aimed the Newton probe at 171.2 s, where benches 1 and 12 overlap; the bisection in
    // that bracket then passed over the contact of benches 1 and 15 at 168.26 s, which opens
    // and closes inside it (found when the search range's end moved and a chunk started at
    // 159.06 s). The probe now stops where any other pair could touch.
    Scenario s;
    s.path.pitch = 0.5;
    s.head_speed = 2.0;
    const Simulation sim(s);
    InlineExecutor one_thread;
    const auto whole = first_contact(sim, 0.0, 190.0, {.on_step = {}, .executor = &one_thread});
    const auto late = first_contact(sim, 159.06, 171.29, {.on_step = {}, .executor = &one_thread});
    ASSERT_TRUE(whole && late);
    EXPECT_EQ(late->bench_a, 1);
    EXPECT_EQ(late->bench_b, 15);
    EXPECT_NEAR(late->time, whole->time, whole->tolerance + late->tolerance);
    EXPECT_GT(clearance(sim.frame(late->time - 1e-8)).distance, 0.0);
    // A scan of the bracket agrees: nothing touches before it.
    for (double t = 159.06; t < late->time - 1e-3; t += 0.01) ASSERT_GT(clearance(sim.frame(t)).distance, 0.0) << t;
}

// The quick test a stretch starts with and a bisection goes by (contact::overlap_of) answers
// yes only where the clearances are <= 0 (over every pair, and clearance(f, kMargin) as the
// search takes it), no only where they are > 0, and unsure only within kSureGap of touching:
// before, at and past the first contact (where more and more benches lie across each other), on
// the whole chain and on its leading benches, at several pitches; and in a scan through the
// contest's contact, on both sides of it.
TEST(Q2, TheOverlapTestAgreesWithTheClearances) {
    contact::Workspace ws;
    BroadPhase broad;
    int yes = 0, no = 0, unsure = 0;
    Frame f;
    const auto check = [&](const std::string& where) {
        const double every = clearance_all_pairs(f).distance;
        const double search = clearance(f, contact::kMargin, broad).distance;
        switch (contact::overlap_of(f, ws)) {
            case contact::Overlap::yes:
                ++yes;
                ASSERT_LE(every, 0.0) << where;
                ASSERT_LE(search, 0.0) << where;
                break;
            case contact::Overlap::no:
                ++no;
                ASSERT_GT(every, 0.0) << where;
                ASSERT_GT(search, 0.0) << where;
                break;
            case contact::Overlap::unsure:
                ++unsure;
                ASSERT_LT(std::abs(every), 2.0 * contact::kSureGap) << where;
                break;
        }
    };
    for (const double pitch : {0.45, 0.55, 0.7}) {
        Scenario s;
        s.path.pitch = pitch;
        const Simulation sim(s);
        const double end = sim.valid_end();
        for (const int lead : {5, 30, 223}) {
            const Simulation part = sim.leading(lead);
            for (double t = std::max(0.0, end - 120.0); t <= end; t += 0.37) {
                part.frame_into(t, f);
                check("pitch " + std::to_string(pitch) + ", t = " + std::to_string(t));
            }
        }
    }
    const Simulation contest{Scenario{}};
    const auto hit = first_contact(contest, 0.0, contest.valid_end());
    ASSERT_TRUE(hit);
    for (int k = -200; k <= 200; ++k) {
        contest.frame_into(hit->time + k * 1e-9, f);
        check("contact + " + std::to_string(k) + " ns");
    }
    EXPECT_GT(yes, 200);
    EXPECT_GT(no, 200);
    EXPECT_GT(unsure, 0);  // the scan through the contact passes within kSureGap of touching
}

// A frame from the minimum-pitch map's runs (width 0.2 m, body boards 2.15 m) where benches 1 and
// 18 have a projected gap of 8e-17 m and a separation that rounds to 0: the search's clearance
// says touching there, so the quick test must not say no (it said so once, and a pitch of the
// map moved by 1e-15 m).
TEST(Q2, TheOverlapTestLeavesARoundedTouchToTheClearance) {
    Scenario s;
    s.bench.width = 0.2;
    s.bench.body_length = 2.15;
    s.path.pitch = 0.3524969561797035;
    const Simulation sim = Simulation(s).leading(21);
    const Frame f = sim.frame(99.005771427176668);
    const Clearance search = clearance(f, contact::kMargin);
    ASSERT_EQ(search.distance, 0.0);
    ASSERT_EQ(search.bench_a, 1);
    ASSERT_EQ(search.bench_b, 18);
    contact::Workspace ws;
    EXPECT_NE(contact::overlap_of(f, ws), contact::Overlap::no);
}
