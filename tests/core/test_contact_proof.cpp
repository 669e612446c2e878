// The first-contact search proves every step it accepts (core/swept_proof.hpp): the proof
// itself, and scenarios built to defeat a search that trusts a rate bound.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

#include "core/swept_proof.hpp"
#include "dragon/analyses.hpp"
#include "dragon/collision.hpp"
#include "dragon/constants.hpp"

using namespace dragon;

namespace {

// The first travel in [x0, x1] (m) where two benches touch, by an independent dense scan every
// `dx` m of head travel (clearance over all pairs through the broad phase), then bisection of
// the clearance's sign to 1e-10 m; none if every sample is apart.
std::optional<double> scan_first_contact(const Simulation& sim, double x0, double x1, double dx) {
    Frame f;
    double last = x0;
    for (double x = x0; x <= x1; x += dx) {
        sim.frame_at_travel_into(x, f);
        if (clearance(f).distance <= 0.0) {
            double lo = last, hi = x;
            while (hi - lo > 1e-10) {
                const double mid = 0.5 * (lo + hi);
                sim.frame_at_travel_into(mid, f);
                (clearance(f).distance <= 0.0 ? hi : lo) = mid;
            }
            return hi;
        }
        last = x;
    }
    return std::nullopt;
}

ContactSearchOptions proved() {
    ContactSearchOptions o;
    o.prove_steps = true;
    return o;
}

// Q3's answer, the pitch below which the dragon touches on the way in (docs/methods.md).
constexpr double kMinPitch = 0.4503373935;

// A pitch this far below the minimum grazes: the benches overlap by about 1e-6 m over a few
// millimetres of head travel, far less than the metres a step of the search covers there.
Scenario grazing(double below) {
    Scenario s;
    s.path.pitch = kMinPitch - below;
    return s;
}

}  // namespace

// The proof of one step: a short step far from any contact is proved; a step over the contest's
// contact is not (it is not contact-free); a step whose end has the handles behind its start is
// not either.
TEST(StepProof, ProvesWhatIsApartAndNothingElse) {
    const Simulation sim(Scenario{});
    contact::SweptWorkspace ws;
    const BenchSpec& spec = sim.scenario().bench;
    const Frame a = sim.frame_at_travel(100.0), b = sim.frame_at_travel(100.2);
    const contact::StepProof p = contact::prove_step(sim.path(), spec, a, b, ws);
    EXPECT_EQ(p.verdict, contact::StepVerdict::proved);
    EXPECT_GT(p.least_gap, 0.0);
    EXPECT_LE(p.least_gap, clearance(a).distance);
    EXPECT_LE(p.least_gap, clearance(b).distance);
    // Over the contact (412.4738 m), from one side to the other: both ends apart or not, the
    // step is not proved.
    const Frame c = sim.frame_at_travel(412.47), d = sim.frame_at_travel(412.48);
    EXPECT_NE(contact::prove_step(sim.path(), spec, c, d, ws).verdict, contact::StepVerdict::proved);
    // Backwards: not a motion the proof knows.
    EXPECT_EQ(contact::prove_step(sim.path(), spec, b, a, ws).verdict, contact::StepVerdict::not_monotone);
}

// The proof's enclosure holds: every sample of the chain inside a proved step keeps each pair at
// least the separation the proof claimed.
TEST(StepProof, TheLeastSeparationProvedHoldsInsideTheStep) {
    const Simulation sim(Scenario{});
    contact::SweptWorkspace ws;
    Frame f;
    for (const double x0 : {50.0, 300.0, 400.0, 410.0, 412.0}) {
        for (const double h : {1e-3, 1e-2, 0.1, 0.5}) {
            const Frame a = sim.frame_at_travel(x0), b = sim.frame_at_travel(x0 + h);
            const contact::StepProof p = contact::prove_step(sim.path(), sim.scenario().bench, a, b, ws);
            if (p.verdict != contact::StepVerdict::proved) continue;
            for (int k = 0; k <= 50; ++k) {
                sim.frame_at_travel_into(x0 + h * k / 50.0, f);
                EXPECT_GE(clearance(f).distance, p.least_gap) << x0 << " + " << h << " at " << k;
            }
        }
    }
}

// On the turnaround's tight arcs a handle may stop or back up and a link turn by more than a
// quarter turn: the proof then rests on the speed bounds (every handle on an arc of the path over
// the step). Every sample inside a step so proved keeps the separation it claimed (25 a step),
// and such steps are met (checked here from the chain itself, not from the proof).
TEST(StepProof, StepsWhereHandlesBackUpAreProvedBySpeedBounds) {
    Scenario sc;
    sc.path.kind = PathKind::turnaround;
    const Simulation sim(sc);
    contact::SweptWorkspace ws;
    Frame f;
    int backing = 0;
    for (double x0 = -12.0; x0 < 12.0; x0 += 0.53) {
        for (const double h : {1e-3, 0.02, 0.2}) {
            const Frame a = sim.frame_at_travel(x0), b = sim.frame_at_travel(x0 + h);
            bool needs_bounds = false;
            for (size_t i = 0; i + 1 < a.handles.size(); ++i) {
                const Place& p0 = a.handles[i].place;
                const Place& p1 = b.handles[i].place;
                if (sim.path().arc(p1) < sim.path().arc(p0) ||
                    sim.path().turning(a.handles[i + 1].place, p1) >= 0.5 * std::numbers::pi)
                    needs_bounds = true;
            }
            const contact::StepProof p = contact::prove_step(sim.path(), sc.bench, a, b, ws);
            if (p.verdict != contact::StepVerdict::proved) continue;
            if (needs_bounds) ++backing;
            for (int k = 0; k <= 24; ++k) {
                sim.frame_at_travel_into(x0 + h * k / 24.0, f);
                EXPECT_GE(clearance(f).distance, p.least_gap) << x0 << " + " << h << " at " << k;
            }
        }
    }
    EXPECT_GE(backing, 5);
}

// A step proved farther apart than `apart_by` keeps every pair so at every sample inside it (all
// pairs, not the broad phase); a step holding a moment closer than apart_by is never so proved.
// On the turnaround, where its least clearance is proved this way, and on the spiral.
TEST(StepProof, AStepProvedApartByABoundKeepsEveryPairFartherThanIt) {
    for (const PathKind kind : {PathKind::turnaround, PathKind::spiral}) {
        Scenario sc;
        sc.path.kind = kind;
        const Simulation sim(sc);
        contact::SweptWorkspace ws;
        Frame f;
        int proved = 0, refused = 0;
        const double x_from = kind == PathKind::spiral ? 300.0 : -8.0;
        for (double x0 = x_from; x0 < x_from + 16.0; x0 += 0.97) {
            for (const double h : {2e-4, 1e-3, 0.05, 0.4}) {
                const Frame a = sim.frame_at_travel(x0), b = sim.frame_at_travel(x0 + h);
                // The least clearance of dense samples inside the step, and a bound under it.
                double least = INFINITY;
                for (int k = 0; k <= 24; ++k) {
                    sim.frame_at_travel_into(x0 + h * k / 24.0, f);
                    least = std::min(least, clearance_all_pairs(f).distance);
                }
                for (const double below : {1e-2, 1e-4}) {
                    const double bound = least - below;
                    const contact::StepProof p = contact::prove_step(sim.path(), sc.bench, a, b, ws, bound);
                    if (p.verdict != contact::StepVerdict::proved) continue;
                    ++proved;
                    EXPECT_GT(p.least_gap, bound);
                    for (int k = 0; k <= 24; ++k) {
                        sim.frame_at_travel_into(x0 + h * (k + 0.5) / 25.0, f);
                        EXPECT_GT(clearance_all_pairs(f).distance, bound) << x0 << " + " << h << " at " << k;
                    }
                }
                // As far apart as a sample inside it, or farther: never proved.
                for (const double above : {0.0, 1e-3}) {
                    const contact::StepProof p = contact::prove_step(sim.path(), sc.bench, a, b, ws, least + above);
                    EXPECT_NE(p.verdict, contact::StepVerdict::proved) << x0 << " + " << h;
                    ++refused;
                }
            }
        }
        EXPECT_GE(proved, 20) << static_cast<int>(kind);
        EXPECT_EQ(refused, 2 * 4 * 17);  // every step, both bounds
    }
}

// The contest's Q2: every step proved, the contact enclosed by what was proved and where the
// benches touch, the enclosure within the printed resolution of the time.
TEST(Q2Proof, TheContestsContactIsProvedFirst) {
    const Simulation sim(Scenario{});
    const auto c = first_contact(sim, 0.0, sim.valid_end(), proved());
    ASSERT_TRUE(c.has_value());
    EXPECT_EQ(c->proof.unproved_steps, 0);
    EXPECT_GT(c->proof.proved_steps, 10);
    EXPECT_EQ(c->proof.proved_from, 0.0);
    EXPECT_EQ(c->enclosure_lo, c->proof.proved_to);
    EXPECT_EQ(c->enclosure_hi, c->travel);
    EXPECT_LE(c->enclosure_lo, c->enclosure_hi);
    EXPECT_LT(c->enclosure_hi - c->enclosure_lo, 1e-9);
    EXPECT_GT(clearance(sim.frame_at_travel(c->enclosure_lo)).distance, 0.0);
    EXPECT_LE(clearance(c->frame).distance, 0.0);
}

// A grazing pass: just below the minimum pitch the benches overlap by about a micrometre over a
// few millimetres of head travel. The search finds it, where a dense independent scan does.
TEST(Q2Proof, AGrazingPassShallowerThanAStepIsFound) {
    for (const double below : {1e-6, 1e-7}) {
        const Simulation sim(grazing(below));
        const double to = boundary_travel(sim);
        const auto c = first_contact_travel(sim, 0.0, to, proved());
        ASSERT_TRUE(c.has_value()) << below;
        EXPECT_EQ(c->proof.unproved_steps, 0);
        // The dense scan, around the contact and before it (every 1e-4 m over the last 0.5 m).
        const auto scan = scan_first_contact(sim, c->travel - 0.5, c->travel + 0.5, 1e-4);
        ASSERT_TRUE(scan.has_value()) << below;
        EXPECT_NEAR(*scan, c->travel, 1e-9) << below;
        // How deep and how long: the graze is shallow and short.
        Frame f;
        double deepest = 0.0, inside = 0.0;
        for (double x = c->travel; x < c->travel + 0.1; x += 1e-5) {
            sim.frame_at_travel_into(x, f);
            const double d = clearance(f).distance;
            if (d <= 0.0) inside += 1e-5, deepest = std::min(deepest, d);
        }
        EXPECT_LT(-deepest, 1e-5) << below;
        EXPECT_LT(inside, 0.2) << below;
    }
}

// A search whose rate bounds choose steps several times too long (rate_safety below 1: the rate
// that peaks inside a step is then well above what the step allowed for) still finds what the
// default search finds, because the proof rejects every step that is not contact-free: it
// subdivides them. Its accepted steps are checked from outside by dense samples.
TEST(Q2Proof, TheProofRejectsStepsTheRateBoundMadeTooLong) {
    std::vector<Scenario> cases = {Scenario{}, grazing(1e-6)};
    cases.push_back(Scenario{});
    cases.back().path.pitch = 0.44;  // a window of contact that opens and closes
    for (const Scenario& s : cases) {
        const Simulation sim(s);
        const double to = std::min(sim.valid_range().to_travel, boundary_travel(sim) + 200.0);
        const auto reference = first_contact_travel(sim, 0.0, to);
        ASSERT_TRUE(reference.has_value());
        for (const double safety : {1.0, 0.25}) {
            ContactSearchOptions o = proved();
            o.rate_safety = safety;
            Frame f;
            o.on_step = [&](double a, double b) {
                for (int k = 1; k <= 8; ++k) {
                    sim.frame_at_travel_into(a + (b - a) * k / 8.0, f);
                    ASSERT_GT(clearance(f).distance, 0.0) << s.path.pitch << " safety " << safety;
                }
            };
            const auto c = first_contact_travel(sim, 0.0, to, o);
            ASSERT_TRUE(c.has_value()) << s.path.pitch << " safety " << safety;
            EXPECT_NEAR(c->travel, reference->travel, 1e-9) << s.path.pitch << " safety " << safety;
            EXPECT_EQ(c->proof.unproved_steps, 0);
            if (safety < 1.0) {
                EXPECT_GT(c->proof.subdivisions, 0) << s.path.pitch;
            }
        }
    }
}

// What the proof adds. The search with its rate bounds checked at each step's end and no proof
// finds the graze even with a rate bound 1000 times too optimistic (the end checks send the long
// steps back: no scenario tried defeats them); with the rate assumption alone (no end checks, no
// proof) it steps over the graze and finds nothing; the proof alone, on the same too optimistic
// steps, finds it.
TEST(Q2Proof, TheRateAssumptionAloneMissesAGrazeTheProofDoesNot) {
    const Simulation sim(grazing(1e-6));
    const double to = boundary_travel(sim);
    const auto truth = first_contact_travel(sim, 0.0, to, proved());
    ASSERT_TRUE(truth.has_value());
    ContactSearchOptions checked;
    checked.rate_safety = 0.001;
    const auto c1 = first_contact_travel(sim, 0.0, to, checked);
    ASSERT_TRUE(c1.has_value());
    EXPECT_NEAR(c1->travel, truth->travel, 1e-9);
    ContactSearchOptions assumed = checked;
    assumed.check_step_ends = false;
    const auto c2 = first_contact_travel(sim, 0.0, to, assumed);
    EXPECT_TRUE(!c2 || c2->travel > truth->travel + 1e-3);
    ContactSearchOptions proof_alone = assumed;
    proof_alone.prove_steps = true;
    const auto c3 = first_contact_travel(sim, 0.0, to, proof_alone);
    ASSERT_TRUE(c3.has_value());
    EXPECT_NEAR(c3->travel, truth->travel, 1e-9);
    EXPECT_EQ(c3->proof.unproved_steps, 0);
    EXPECT_GT(c3->proof.subdivisions, 0);
}

// Where the benches stay far apart (the turnaround's window, closest 0.28 m) the enclosures prove
// steps several times as long as the rates allow: the proved search takes far fewer steps than
// the rates alone choose, and each of its steps, past the rates or not, is contact-free at dense
// samples inside it.
TEST(Q2Proof, StepsPastTheRatesStandOnTheirProof) {
    Scenario sc;
    sc.path.kind = PathKind::turnaround;
    const Simulation sim(sc);
    const Simulation unit = sim.at_speed(1.0);
    int rate_steps = 0;
    ContactSearchOptions rates;
    rates.on_step = [&](double, double) { ++rate_steps; };
    EXPECT_FALSE(first_contact_travel(sim, -100.0, 100.0, rates).has_value());
    ContactProof proof;
    ContactSearchOptions o = proved();
    o.proof = &proof;
    Frame f;
    double covered = 0.0;
    o.on_step = [&](double a, double b) {
        covered += b - a;
        for (int k = 1; k < 16; ++k) {
            unit.frame_at_travel_into(a + (b - a) * k / 16.0, f);
            ASSERT_GT(clearance(f).distance, 0.2) << a << " .. " << b;
        }
    };
    EXPECT_FALSE(first_contact_travel(sim, -100.0, 100.0, o).has_value());
    EXPECT_EQ(proof.unproved_steps, 0);
    EXPECT_EQ(proof.proved_to, 100.0);
    EXPECT_NEAR(covered, 200.0, 1e-9);
    EXPECT_LT(2 * proof.proved_steps, rate_steps) << proof.proved_steps << " against " << rate_steps;
}

// Asked to prove its steps, the search also proves the valid motion they assume over its range:
// on the turnaround, whose tight arcs the default walk leaves to its rates, every step of it.
TEST(Q2Proof, TheValidMotionTheStepsAssumeIsProvedToo) {
    Scenario sc;
    sc.path.kind = PathKind::turnaround;
    const Simulation sim(sc);
    ContactProof proof;
    ContactSearchOptions o;
    o.prove_steps = true;
    o.proof = &proof;
    EXPECT_FALSE(first_contact_travel(sim, -100.0, 100.0, o).has_value());
    EXPECT_TRUE(proof.motion_checked);
    EXPECT_GT(proof.motion.proved_steps, 0);
    EXPECT_EQ(proof.motion.unproved_steps, 0);
    // The default walk over the same range leaves steps to their rates.
    JamSearchStats plain;
    find_jam(sim.path(), sc.bench, sim.head_arc(0.0), 1.0, -100.0, 100.0, &plain);
    EXPECT_GT(plain.unproved_steps, 0);
    ContactProof unproved;
    o.prove_steps = false;
    o.proof = &unproved;
    first_contact_travel(sim, -100.0, 100.0, o);
    EXPECT_FALSE(unproved.motion_checked);
}

// At the ratio 3:1 the turnaround's tight arc leaves steps that neither the handles' motion nor
// their speed bounds enclose at the length the rates choose; shorter ones they do (the bounds
// tighten), so the search takes them shorter, and every step up to the end of the valid motion
// is proved (StepProof's tests check what such steps claim against samples inside them).
TEST(Q2Proof, StepsTheSpeedBoundsEncloseOnlyWhenShortAreTakenShorter) {
    Scenario sc;
    sc.path.kind = PathKind::turnaround;
    sc.path.arc_ratio = 3.0;
    const Simulation sim(sc);
    const CollideAnswer motion = first_contact_of_motion(sim);  // the window cut to the valid motion
    ASSERT_TRUE(motion.jam.has_value());
    ContactProof proof;
    ContactSearchOptions o;
    o.prove_steps = true;
    o.proof = &proof;
    const double from = 5.0, to = motion.window.to_travel;  // the S-curve's arcs, up to the jam
    EXPECT_FALSE(first_contact_travel(sim, from, to, o).has_value());
    EXPECT_EQ(proof.unproved_steps, 0);
    EXPECT_GT(proof.proved_steps, 0);
    EXPECT_EQ(proof.proved_to, to);
    EXPECT_GT(proof.subdivisions, 0);
    // The same range at the length the rates choose, with no step taken shorter for its enclosure,
    // is what the search met before (the proofs asked of each step as it comes): some fail.
    contact::SweptWorkspace ws;
    const Simulation unit = sim.at_speed(1.0);
    int not_enclosed = 0;
    for (double x = from; x + 0.25 < to; x += 0.25)
        if (contact::prove_step(sim.path(), sc.bench, unit.frame(x), unit.frame(x + 0.25), ws).verdict ==
            contact::StepVerdict::not_monotone)
            ++not_enclosed;
    EXPECT_GT(not_enclosed, 0);
}
