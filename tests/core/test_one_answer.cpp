// One dragon, one answer: every answer depends on the scenario alone, not on the head's speed
// (which only sets the clock), the number of workers, the order moments are asked in, or which
// analysis asked.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "dragon/analyses.hpp"
#include "dragon/constants.hpp"
#include "dragon/contest.hpp"
#include "dragon/executor.hpp"
#include "dragon/turnaround.hpp"

using namespace dragon;

namespace {

Scenario at_speed(Scenario s, double v) {
    s.head_speed = v;
    return s;
}

Scenario turnaround(double turn_pitch = 1.7) {
    Scenario s;
    s.path.kind = PathKind::turnaround;
    s.path.turn_pitch = turn_pitch;
    return s;
}

// Two contacts are one event: the same benches, point and travel, bit for bit, and times that
// are that travel at each one's head speed.
void expect_same_contact(const Contact& a, const Contact& b, double speed_a, double speed_b) {
    EXPECT_EQ(a.bench_a, b.bench_a);
    EXPECT_EQ(a.bench_b, b.bench_b);
    EXPECT_EQ(a.travel, b.travel);
    EXPECT_EQ(a.point, b.point);
    EXPECT_EQ(a.head_radius, b.head_radius);
    EXPECT_EQ(a.time, a.travel / speed_a);
    EXPECT_EQ(b.time, b.travel / speed_b);
}

}  // namespace

TEST(OneAnswer, FirstContactIsTheSameAtAnyHeadSpeed) {
    for (const Scenario& base : {Scenario{}, turnaround(0.44)}) {
        const CollideAnswer ref = first_contact_of_motion(Simulation(base));
        ASSERT_TRUE(ref.contact);
        for (double v : {0.05, 5.0}) {
            const CollideAnswer a = first_contact_of_motion(Simulation(at_speed(base, v)));
            ASSERT_TRUE(a.contact) << v;
            expect_same_contact(*a.contact, *ref.contact, v, 1.0);
            EXPECT_EQ(a.contact->steps, ref.contact->steps) << v;
            EXPECT_EQ(a.window.to_travel, ref.window.to_travel) << v;
            // How closely the time is known scales too: 1e-11 m of travel.
            EXPECT_NEAR(a.contact->tolerance, tol::travel / v, 1e-3 * tol::travel / v) << v;
        }
    }
}

TEST(OneAnswer, TheValidMotionIsTheSameAtAnyHeadSpeed) {
    for (const Scenario& base : {Scenario{}, [] {
             Scenario s = turnaround();
             s.path.arc_ratio = 3.0;
             return s;
         }()}) {
        const ValidRange ref = Simulation(base).valid_range();
        ASSERT_TRUE(ref.after);
        for (double v : {0.05, 5.0}) {
            const ValidRange r = Simulation(at_speed(base, v)).valid_range();
            ASSERT_TRUE(r.after) << v;
            EXPECT_EQ(r.after->travel, ref.after->travel) << v;
            EXPECT_EQ(r.after->handle, ref.after->handle) << v;
            EXPECT_EQ(r.after->kind, ref.after->kind) << v;
            EXPECT_EQ(r.after->time, ref.after->travel / v) << v;
            EXPECT_EQ(r.to_travel, ref.to_travel) << v;
        }
    }
}

TEST(OneAnswer, TheEndOfTheMotionDoesNotDependOnWhatWasAskedFirst) {
    // A simulation asked for a late moment first (its jam walk then takes long strides before
    // anyone needs the end) finds the end found by one asked for the whole range at once.
    const Simulation whole{Scenario{}};
    const ValidRange ref = whole.valid_range();
    const Simulation piecemeal{Scenario{}};
    (void)piecemeal.frame(431.0);
    (void)piecemeal.frame(3.0);
    (void)piecemeal.frame(432.9);
    const ValidRange r = piecemeal.valid_range();
    ASSERT_TRUE(r.after && ref.after);
    EXPECT_EQ(r.after->travel, ref.after->travel);
    EXPECT_EQ(r.after->point, ref.after->point);
}

TEST(OneAnswer, FirstContactDoesNotDependOnTheWorkers) {
    const Simulation sim{Scenario{}};
    InlineExecutor one;
    ThreadPool two(2), three(3);
    std::optional<Contact> ref;
    for (Executor* ex : std::initializer_list<Executor*>{&one, &two, &three}) {
        ContactSearchOptions o;
        o.executor = ex;
        const std::optional<Contact> c = first_contact(sim, 0.0, sim.valid_end(), o);
        ASSERT_TRUE(c);
        if (!ref) {
            ref = c;
            continue;
        }
        expect_same_contact(*c, *ref, 1.0, 1.0);
        EXPECT_EQ(c->steps, ref->steps) << ex->workers() << " workers";
    }
}

TEST(OneAnswer, TheTurnaroundReportsTheFirstContactCollideFinds) {
    // At turn pitch 0.44 benches 1 and 19 touch 28 s before the turn; a search from t = 0 alone
    // would find a later contact (benches 1 and 15) instead.
    const Scenario s = turnaround(0.44);
    const RunClearance check = min_clearance(s);
    const CollideAnswer c = collide(Simulation(s), kTurnaroundWindow);
    ASSERT_TRUE(check.first_contact && c.contact);
    expect_same_contact(*check.first_contact, *c.contact, 1.0, 1.0);
    EXPECT_EQ(c.contact->bench_b, 19);
    EXPECT_LT(c.contact->time, 0.0);
    EXPECT_FALSE(check.collision_free());
    // The clearance is only looked at up to the contact: it is the contact, no overlap.
    EXPECT_EQ(check.distance, 0.0);
    EXPECT_EQ(check.time, c.contact->time);
    EXPECT_EQ(check.bench_b, c.contact->bench_b);
    const std::optional<Contact> from_turn = first_contact(Simulation(s), 0.0, 100.0);
    ASSERT_TRUE(from_turn);
    EXPECT_GT(from_turn->time, 0.0);
}

TEST(OneAnswer, TheTurnaroundCheckIsTheSameAtAnyHeadSpeed) {
    // Collision-free at 1 m/s over 100 m either side of the turn: the same at 0.05 m/s, where
    // a window of 100 s would have seen only 5 m of it.
    for (double pitch : {1.7, 0.5}) {
        const RunClearance ref = min_clearance(turnaround(pitch));
        for (double v : {0.05, 5.0}) {
            const RunClearance c = min_clearance(at_speed(turnaround(pitch), v));
            EXPECT_EQ(c.collision_free(), ref.collision_free()) << pitch << " " << v;
            EXPECT_EQ(c.distance, ref.distance) << pitch << " " << v;
            EXPECT_EQ(c.travel, ref.travel) << pitch << " " << v;
            EXPECT_EQ(c.bench_a, ref.bench_a) << pitch << " " << v;
            EXPECT_EQ(c.bench_b, ref.bench_b) << pitch << " " << v;
            if (ref.first_contact) expect_same_contact(*c.first_contact, *ref.first_contact, v, 1.0);
        }
    }
}

TEST(OneAnswer, TheMinimumPitchIsTheSameAtAnyHeadSpeed) {
    MinPitchOptions o;
    o.grid = 0.01;
    const MinPitch ref = min_pitch(Scenario{}, 0.42, 0.48, o);
    const MinPitch slow = min_pitch(at_speed(Scenario{}, 0.05), 0.42, 0.48, o);
    EXPECT_EQ(slow.pitch, ref.pitch);
    ASSERT_EQ(slow.intervals.size(), ref.intervals.size());
    for (size_t k = 0; k < ref.intervals.size(); ++k) EXPECT_EQ(slow.intervals[k].lo, ref.intervals[k].lo);
}

TEST(OneAnswer, TheContestSolvesWhatItCanReachAndSaysWhatItLeftOut) {
    // Ratio 3: the S-curve is too tight for the head's link at 15.15 s of the turn. Q4's table
    // holds -100..15 s, and says the 85 rows after it are left out; Q5 says it searched only so far.
    Scenario s;
    s.path.arc_ratio = 3.0;
    ContestOptions o;
    o.questions = {Question::q4, Question::q5};
    const ContestAnswers a = solve_contest(s, o);
    ASSERT_TRUE(a.q4 && a.q5 && a.q4_jam);
    EXPECT_EQ(a.q4->frames.size(), 116u);
    EXPECT_EQ(a.q4->frames.back().time, 15.0);
    EXPECT_EQ(a.q4->rows_left_out, 85);
    ASSERT_TRUE(a.q4->jam);
    EXPECT_NEAR(a.q4->jam->time, a.q4_jam->time, 0.0);
    ASSERT_TRUE(a.q5->jam);
    EXPECT_EQ(a.q5->jam->travel, a.q4_jam->travel);
    // Start turn 8: the contest's pitches put the head inside the turning space; Q3 searches
    // from just above the smallest pitch that does not, and says why.
    Scenario late;
    late.path.start_turn = 8.0;
    ContestOptions q3;
    q3.questions = {Question::q3};
    const ContestAnswers b = solve_contest(late, q3);
    ASSERT_TRUE(b.q3 && b.q3_range);
    EXPECT_FALSE(b.q3_range->moved.empty());
    EXPECT_GT(b.q3->search_lo * late.path.start_turn, late.path.turn_radius);
}

TEST(OneAnswer, TablesPastTheFirstContactSaySo) {
    // Q1 at pitch 0.45 m: the benches touch before 300 s, and the table says from where.
    Scenario s;
    s.path.pitch = 0.45;
    ContestOptions o;
    o.questions = {Question::q1};
    const ContestAnswers a = solve_contest(s, o);
    ASSERT_TRUE(a.q1);
    ASSERT_TRUE(a.q1->past_contact);
    const CollideAnswer c = first_contact_of_motion(Simulation(s));
    ASSERT_TRUE(c.contact);
    expect_same_contact(*a.q1->past_contact, *c.contact, 1.0, 1.0);
    EXPECT_LT(a.q1->past_contact->time, 300.0);
}
