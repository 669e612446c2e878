// The second-order enclosures of a step (core/handle_accel.hpp, core/swept_proof.cpp item 3b):
// the bounds on every handle's second derivative in head travel against finite differences, and
// each kind of enclosure, on its own, against dense samples of the chain inside the step.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/handle_accel.hpp"
#include "core/swept_proof.hpp"
#include "dragon/analyses.hpp"
#include "dragon/collision.hpp"

using namespace dragon;

namespace {

// What handle_accel_bounds assumes of a step, checked from the chain itself: every handle ends
// ahead of where it began, every link's hull and every handle's own arc turn by less than pi/2.
// Fills the turnings it takes.
bool forward_and_gentle(const Path& path, const Frame& a, const Frame& b, std::vector<double>& hull,
                        std::vector<double>& own) {
    const size_t nh = a.handles.size();
    hull.assign(nh - 1, 0.0);
    own.assign(nh, 0.0);
    for (size_t k = 0; k < nh; ++k) {
        if (path.arc(b.handles[k].place) < path.arc(a.handles[k].place)) return false;
        own[k] = path.turning(a.handles[k].place, b.handles[k].place);
        if (k + 1 < nh) hull[k] = path.turning(a.handles[k + 1].place, b.handles[k].place);
        if (own[k] >= 1.5 || (k + 1 < nh && hull[k] >= 1.5)) return false;
    }
    return true;
}

struct Step {
    PathKind kind;
    double x0, h;  // m of head travel
};

std::vector<Step> steps() {
    std::vector<Step> out;
    for (const double x0 : {100.0, 300.0, 405.0, 409.8, 412.0})
        for (const double h : {1e-2, 0.1, 0.5}) out.push_back({PathKind::spiral, x0, h});
    for (const double x0 : {-60.0, -9.0, -4.0, 0.5, 6.0, 40.0})
        for (const double h : {1e-2, 0.1, 0.5}) out.push_back({PathKind::turnaround, x0, h});
    return out;
}

}  // namespace

// Every handle's |P''| and speed at 17 moments inside each step, by central differences of the
// chain's positions (1e-3 m of head travel apart: truncation and rounding near 1e-7), stay below
// the bounds made from the step's two ends; on the short steps the bound is close to the largest
// sampled (the intervals shrink with the step: the bound is not the curvature's worst case).
TEST(HandleAccel, BoundsEveryHandlesBendInsideTheStep) {
    int checked = 0, tight = 0;
    for (const Step& st : steps()) {
        Scenario sc;
        sc.path.kind = st.kind;
        const Simulation sim(sc);
        const Path& path = sim.path();
        const Frame a = sim.frame_at_travel(st.x0), b = sim.frame_at_travel(st.x0 + st.h);
        std::vector<double> hull, own, accel, speed;
        if (!forward_and_gentle(path, a, b, hull, own)) continue;
        ASSERT_TRUE(contact::handle_accel_bounds(path, sc.bench, a, b, hull, own, accel, speed));
        ++checked;
        const size_t nh = a.handles.size();
        std::vector<double> largest(nh, 0.0);
        constexpr double kDelta = 1e-3;
        for (int s = 0; s <= 16; ++s) {
            const double x = st.x0 + st.h * s / 16.0;
            const Frame m = sim.frame_at_travel(x), lo = sim.frame_at_travel(x - kDelta), hi = sim.frame_at_travel(x + kDelta);
            for (size_t k = 0; k < nh; ++k) {
                const Vec2 second = (hi.handles[k].pos - 2.0 * m.handles[k].pos + lo.handles[k].pos) / (kDelta * kDelta);
                largest[k] = std::max(largest[k], norm(second));
                EXPECT_LE(norm(second), accel[k] + 1e-6) << static_cast<int>(st.kind) << " " << st.x0 << " + " << st.h
                                                          << " handle " << k << " at " << s;
                EXPECT_LE(std::abs(m.handles[k].speed / m.handles[0].speed), speed[k] + 1e-12)
                    << st.x0 << " + " << st.h << " handle " << k;
            }
        }
        if (st.h == 1e-2) {
            // Not the curvature's worst case: near the head, where a search watches benches
            // near a contact, within a half of the largest sampled; down the chain, where each
            // link adds the width of its interval of the ratio's rate (to about twice the sampled
            // at the tail), within 3 times.
            for (size_t k = 0; k < nh; ++k)
                EXPECT_LE(accel[k], (k < 40 ? 1.5 : 3.0) * largest[k] + 1e-3) << st.x0 << " handle " << k;
            ++tight;
        }
    }
    EXPECT_GE(checked, 25);
    EXPECT_GE(tight, 8);
}

// Each kind of enclosure on its own: a step it proves keeps every pair (all of them, not the
// broad phase) at least the separation it claims at 25 moments inside, and one asked to prove
// a separation a sample inside falls short of is never proved. On the spiral up to the contest's
// contact and on the turnaround (the turned frame's second order, the spiral's own, proves
// nothing there: 13 of its 15 steps on the spiral, against 21 of 33 for the fixed frame's).
TEST(SecondOrderProof, EachEnclosureAloneKeepsWhatItProves) {
    for (const contact::Enclosures which : {contact::Enclosures::first_order, contact::Enclosures::second_order,
                                            contact::Enclosures::second_order_turned}) {
        int proved = 0;
        for (const Step& st : steps()) {
            Scenario sc;
            sc.path.kind = st.kind;
            const Simulation sim(sc);
            contact::SweptWorkspace ws;
            const Frame a = sim.frame_at_travel(st.x0), b = sim.frame_at_travel(st.x0 + st.h);
            double least = INFINITY;
            Frame f;
            for (int k = 0; k <= 24; ++k) {
                sim.frame_at_travel_into(st.x0 + st.h * k / 24.0, f);
                least = std::min(least, clearance_all_pairs(f).distance);
            }
            const contact::StepProof p = contact::prove_step(sim.path(), sc.bench, a, b, ws, 0.0, which);
            if (p.verdict == contact::StepVerdict::proved) {
                ++proved;
                EXPECT_LE(p.least_gap, least) << static_cast<int>(which) << " " << st.x0 << " + " << st.h;
            }
            const contact::StepProof q = contact::prove_step(sim.path(), sc.bench, a, b, ws, least, which);
            EXPECT_NE(q.verdict, contact::StepVerdict::proved) << static_cast<int>(which) << " " << st.x0 << " + " << st.h;
        }
        EXPECT_GE(proved, which == contact::Enclosures::second_order_turned ? 13 : 15) << static_cast<int>(which);
    }
}

// Near the contest's contact, where the head's board passes benches 10 and 12 within millimetres
// and then meets bench 9, the second order proves more of the steps
// from 405 to 412.4 m of head travel, 3 mm to 10 cm long, than the first order.
TEST(SecondOrderProof, ProvesMoreStepsNearAContactThanTheFirstOrder) {
    const Simulation sim(Scenario{});
    contact::SweptWorkspace ws;
    int first = 0, second = 0;
    for (double x0 = 405.0; x0 < 412.4; x0 += 0.37) {
        for (const double h : {3e-3, 1e-2, 3e-2, 0.1}) {
            if (x0 + h > 412.47) continue;
            const Frame a = sim.frame_at_travel(x0), b = sim.frame_at_travel(x0 + h);
            const auto proves = [&](contact::Enclosures which) {
                return contact::prove_step(sim.path(), sim.scenario().bench, a, b, ws, 0.0, which).verdict ==
                       contact::StepVerdict::proved;
            };
            first += proves(contact::Enclosures::first_order);
            second += proves(contact::Enclosures::second_order);
        }
    }
    EXPECT_GT(second, first);
}

namespace {

// The longest step from x0 (m of head travel), of 1 mm doubled up to 8 m, that `which` proves
// on the contest's dragon; 0 when none.
double longest_proved(const Simulation& sim, double x0, contact::Enclosures which, contact::SweptWorkspace& ws) {
    const Frame a = sim.frame_at_travel(x0);
    double longest = 0.0;
    for (double h = 1e-3; h <= 8.0 && x0 + h < sim.valid_end(); h *= 2.0) {
        const Frame b = sim.frame_at_travel(x0 + h);
        if (contact::prove_step(sim.path(), sim.scenario().bench, a, b, ws, 0.0, which).verdict ==
            contact::StepVerdict::proved)
            longest = h;
    }
    return longest;
}

}  // namespace

// On the spiral a step is a cell of one pitch (pitch_proof.hpp), and its second order in the
// frame turned with the head, where only the chain's change of shape is left, is far tighter
// than the fixed frame's: from 40 starts between 380 m and the contest's contact its longest
// proved step (in powers of two) is never shorter, and together they are about three times as
// long (10.1 m against 3.4).
TEST(SecondOrderProof, TheTurnedFrameProvesLongerStepsOnTheSpiral) {
    const Simulation sim(Scenario{});
    contact::SweptWorkspace ws;
    double fixed = 0.0, turned = 0.0;
    for (int k = 0; k < 40; ++k) {
        const double x0 = 380.0 + (412.47 - 380.0) * (1.0 - std::pow(0.5, k / 4.0));
        const double f = longest_proved(sim, x0, contact::Enclosures::second_order, ws);
        const double t = longest_proved(sim, x0, contact::Enclosures::second_order_turned, ws);
        EXPECT_GE(t, f) << x0;
        fixed += f;
        turned += t;
    }
    EXPECT_GT(turned, 2.5 * fixed) << "fixed " << fixed << " m, turned " << turned << " m";
}

// A step is a cell only when it is one: not with the head moving out (the ends swapped), and not
// where a link's span reaches a quarter turn (near the spiral's centre, at pitch 1.7 m), where
// the turned frame's proof declines (not_monotone) and the search falls back on the others.
TEST(SecondOrderProof, TheTurnedFrameDeclinesWhatIsNotACell) {
    const Simulation sim(Scenario{});
    contact::SweptWorkspace ws;
    const Path& path = sim.path();
    const BenchSpec& bench = sim.scenario().bench;
    const Frame a = sim.frame_at_travel(300.0), b = sim.frame_at_travel(300.1);
    EXPECT_EQ(contact::prove_step(path, bench, a, b, ws, 0.0, contact::Enclosures::second_order_turned).verdict,
              contact::StepVerdict::proved);
    EXPECT_EQ(contact::prove_step(path, bench, b, a, ws, 0.0, contact::Enclosures::second_order_turned).verdict,
              contact::StepVerdict::not_monotone);
    Scenario wide;
    wide.path.pitch = 1.7;
    const Simulation centre(wide);
    const double end = centre.valid_end();
    const Frame c = centre.frame_at_travel(end - 0.2), d = centre.frame_at_travel(end - 0.1);
    // Some link spans a quarter turn or more there (the cell's bounds fail), checked directly.
    bool wide_span = false;
    for (size_t m = 0; m + 1 < d.handles.size(); ++m)
        wide_span = wide_span || d.handles[m + 1].place.u - d.handles[m].place.u >= 0.5 * std::numbers::pi;
    ASSERT_TRUE(wide_span);
    EXPECT_EQ(contact::prove_step(centre.path(), bench, c, d, ws, 0.0, contact::Enclosures::second_order_turned).verdict,
              contact::StepVerdict::not_monotone);
}
