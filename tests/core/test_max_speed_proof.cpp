// Q5's proof: the enclosure of the largest speed ratio over the whole window, checked against
// independent dense scans (speed_ratio_at, which shares only the chain solver).
#include <algorithm>
#include <cmath>
#include <random>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "core/chain_front.hpp"
#include "core/speed_bound.hpp"
#include "dragon/chain.hpp"
#include "dragon/executor.hpp"
#include "dragon/turnaround.hpp"

using namespace dragon;

namespace {

Scenario turnaround_scenario(double arc_ratio = 2.0, double turn_pitch = 1.7) {
    Scenario s;
    s.path.kind = PathKind::turnaround;
    s.path.arc_ratio = arc_ratio;
    s.path.turn_pitch = turn_pitch;
    return s;
}

// The search asked to prove its maximum (it is opt-in: dragon max-speed --prove).
const MaxSpeedOptions kProve{true};

// The largest ratio on [from, to] in steps of `step`, m of head arc.
double dense_max(const Path& path, const BenchSpec& bench, double from, double to, double step) {
    double best = 0.0;
    const int n = static_cast<int>(std::ceil((to - from) / step));
    for (int k = 0; k <= n; ++k) best = std::max(best, speed_ratio_at(path, bench, std::min(to, from + k * step)).ratio);
    return best;
}

// The chain at head arc s in f (its first `handles`; 0: all of them) and its facts in c.
void facts_at(const Path& path, const BenchSpec& bench, double s, Frame& f, speed::ChainFacts& c, int handles = 0) {
    solve_chain_front(path, bench, s, 1.0, handles > 0 ? handles : bench.handle_count(), f);
    speed::gather(path, f, c);
}

// The proof's claims checked against dense scans of the window it searched: 1 cm steps over
// the whole window, 1e-4 m steps within 0.2 m of the maximum found, and, around every point
// of the 1 cm scan within 1e-3 of the largest, 1e-4 m steps too (a second peak nearly as high).
void check_enclosure(const Scenario& sc, const MaxSpeed& m) {
    ASSERT_TRUE(m.proof.has_value());
    const MaxSpeedProof& p = *m.proof;
    ASSERT_TRUE(p.proved) << p.unproved << " stretches unproved";
    EXPECT_EQ(p.unproved, 0);
    EXPECT_STREQ(p.method(), "lipschitz bound");
    EXPECT_LE(p.ratio_lo, m.ratio);
    EXPECT_GE(p.ratio_hi, m.ratio);
    // (3) the bound is within the stated tolerance of the maximum found, and the found maximum
    // within its rounding model (far below the tolerance) of the lower end.
    EXPECT_LE(p.ratio_hi - m.ratio, p.tolerance * m.ratio);
    EXPECT_LE(m.ratio - p.ratio_lo, 1e-11 * m.ratio);
    EXPECT_LE(p.max_head_speed_lo, m.max_head_speed);
    EXPECT_GE(p.max_head_speed_hi, m.max_head_speed);

    const TurnaroundPath path(design_s_curve(sc));
    const double start = m.head_arc - m.travel;
    const double from = start + m.window.from_travel, to = start + m.window.to_travel;
    double coarse = 0.0;
    std::vector<double> near;
    for (double x = from; x <= to; x += 0.01) {
        const double r = speed_ratio_at(path, sc.bench, x).ratio;
        coarse = std::max(coarse, r);
        ASSERT_LE(r, p.ratio_hi) << "at s = " << x;
        near.push_back(r);
    }
    double fine = dense_max(path, sc.bench, std::max(from, m.head_arc - 0.2), std::min(to, m.head_arc + 0.2), 1e-4);
    for (size_t k = 0; k < near.size(); ++k) {
        if (near[k] < coarse - 1e-3) continue;
        const double x = from + 0.01 * static_cast<double>(k);
        fine = std::max(fine, dense_max(path, sc.bench, std::max(from, x - 0.01), std::min(to, x + 0.01), 1e-4));
    }
    // (1) the bound encloses the dense scan's maximum.
    EXPECT_LE(fine, p.ratio_hi);
    EXPECT_GE(std::max(fine, coarse), p.ratio_lo - p.tolerance * m.ratio);
}

}  // namespace

TEST(MaxSpeedProof, EnclosesTheContestsMaximumWithinTheTolerance) {
    const Scenario sc = turnaround_scenario();
    const MaxSpeed m = max_head_speed(sc, 2.0, kTurnaroundWindow, nullptr, kProve);
    check_enclosure(sc, m);
    const MaxSpeedProof& p = *m.proof;
    EXPECT_GT(p.stretches, 0);
    EXPECT_GT(p.narrowest, 0.0);
    // The valid motion the bounds assume is proved over the window too, every step of it.
    EXPECT_GT(p.motion.proved_steps, 0);
    EXPECT_EQ(p.motion.unproved_steps, 0);
    // The printed answer (6 decimals of m/s) is proved: both ends of the enclosure print alike.
    EXPECT_EQ(fmt::format("{:.6f}", p.max_head_speed_lo), fmt::format("{:.6f}", p.max_head_speed_hi));
    EXPECT_EQ(fmt::format("{:.6f}", p.max_head_speed_lo), fmt::format("{:.6f}", m.max_head_speed));
}

TEST(MaxSpeedProof, TheSearchWithoutTheProofFindsTheSameMaximum) {
    const Scenario sc = turnaround_scenario();
    const MaxSpeed proved = max_head_speed(sc, 2.0, kTurnaroundWindow, nullptr, kProve);
    MaxSpeedOptions plain;
    plain.prove = false;
    const MaxSpeed sampled = max_head_speed(sc, 2.0, kTurnaroundWindow, nullptr, plain);
    EXPECT_FALSE(sampled.proof.has_value());
    EXPECT_GE(proved.ratio, sampled.ratio);
    EXPECT_LE(sampled.ratio, proved.proof->ratio_hi);
    EXPECT_GE(sampled.ratio, proved.proof->ratio_lo - proved.proof->tolerance * proved.ratio);
}

// The scan and the stretches' bounds run on the executor's workers: the answer, its proof and
// every count are the same, bit for bit, on one worker or several.
TEST(MaxSpeedProof, TheAnswerIsTheSameOnAnyNumberOfWorkers) {
    const Scenario sc = turnaround_scenario();
    ThreadPool pool(3);
    for (const bool prove : {false, true}) {
        MaxSpeedOptions o;
        o.prove = prove;
        const MaxSpeed one = max_head_speed(sc, 2.0, kTurnaroundWindow, nullptr, o);
        const MaxSpeed many = max_head_speed(sc, 2.0, kTurnaroundWindow, &pool, o);
        EXPECT_EQ(one.ratio, many.ratio) << prove;
        EXPECT_EQ(one.head_arc, many.head_arc) << prove;
        EXPECT_EQ(one.tied, many.tied) << prove;
        EXPECT_EQ(one.evaluations, many.evaluations) << prove;
        EXPECT_EQ(one.candidates, many.candidates) << prove;
        ASSERT_EQ(one.proof.has_value(), prove);
        ASSERT_EQ(many.proof.has_value(), prove);
        if (!prove) continue;
        EXPECT_EQ(one.proof->ratio_lo, many.proof->ratio_lo);
        EXPECT_EQ(one.proof->ratio_hi, many.proof->ratio_hi);
        EXPECT_EQ(one.proof->stretches, many.proof->stretches);
        EXPECT_EQ(one.proof->subdivisions, many.proof->subdivisions);
        EXPECT_EQ(one.proof->narrowest, many.proof->narrowest);
    }
}

TEST(MaxSpeedProof, EnclosesRandomScenariosMaxima) {
    std::mt19937 rng(20261127);
    std::uniform_real_distribution<double> ratio(1.2, 3.0), pitch(1.6, 2.2);
    int checked = 0;
    for (int trial = 0; trial < 5; ++trial) {
        const Scenario sc = turnaround_scenario(ratio(rng), pitch(rng));
        SCOPED_TRACE(fmt::format("arc_ratio {} turn_pitch {}", sc.path.arc_ratio, sc.path.turn_pitch));
        const MaxSpeed m = max_head_speed(sc, 2.0, kTurnaroundWindow, nullptr, kProve);
        if (m.unbounded) continue;  // no head speed will do: nothing to enclose
        check_enclosure(sc, m);
        ++checked;
    }
    EXPECT_GE(checked, 3);
}

// Where a handle backs up (arc ratio 2.8: handle 1 stops and backs before the jam), the rear
// handles' arcs come from the slope bound of Lemma A', not from their end places.
TEST(MaxSpeedProof, EnclosesTheMaximumWhereAHandleBacksUp) {
    const Scenario sc = turnaround_scenario(2.8, 1.7);
    const MaxSpeed m = max_head_speed(sc, 2.0, kTurnaroundWindow, nullptr, kProve);
    ASSERT_FALSE(m.unbounded);
    const TurnaroundPath path(design_s_curve(sc));
    const double start = m.head_arc - m.travel;
    bool backs = false;
    Frame f;
    for (double x = start + m.window.from_travel; x <= start + m.window.to_travel && !backs; x += 0.01) {
        solve_chain(path, sc.bench, x, 1.0, f);
        for (const Handle& h : f.handles) backs = backs || h.speed < 0.0;
    }
    ASSERT_TRUE(backs) << "no handle backs up in the window: the case is not the one meant";
    check_enclosure(sc, m);
}

// (2) A scan too coarse to see the peak (one sample every 10 links): the sampled search alone
// reports less than the true maximum; the proof, whose bounds see every stretch whole, splits
// its way to the peak and encloses the true maximum.
TEST(MaxSpeedProof, FindsAPeakTheCoarseScanMissed) {
    const Scenario sc = turnaround_scenario();
    const MaxSpeed reference = max_head_speed(sc, 2.0, kTurnaroundWindow, nullptr, kProve);
    MaxSpeedOptions coarse;
    coarse.samples_per_link = 0.1;
    coarse.prove = false;
    const MaxSpeed missed = max_head_speed(sc, 2.0, kTurnaroundWindow, nullptr, coarse);
    ASSERT_LT(missed.ratio, reference.proof->ratio_lo - 1e-6) << "the coarse scan found the peak: not adversarial";
    coarse.prove = true;
    const MaxSpeed m = max_head_speed(sc, 2.0, kTurnaroundWindow, nullptr, coarse);
    check_enclosure(sc, m);
    EXPECT_GE(m.proof->subdivisions, 10);
    // The same enclosure as the fine scan's, within the tolerance.
    EXPECT_LE(m.proof->ratio_lo, reference.proof->ratio_hi);
    EXPECT_GE(m.proof->ratio_hi, reference.proof->ratio_lo);
}

// Each stretch's bound directly, on stretches 0.4 to 10 times as long as the proof's first ones
// (0.02 to 0.5 m of head travel) all over the window, kinks included: no sample inside exceeds it.
TEST(MaxSpeedProof, AStretchsBoundHoldsInsideIt) {
    const Scenario sc = turnaround_scenario();
    const TurnaroundPath path(design_s_curve(sc));
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> where(-100.0, 99.5), width(0.02, 0.5);
    Frame f0, f1;
    speed::ChainFacts c0, c1;
    int bounded = 0;
    for (int trial = 0; trial < 60; ++trial) {
        const double a = where(rng), b = a + width(rng);
        facts_at(path, sc.bench, a, f0, c0);
        facts_at(path, sc.bench, b, f1, c1);
        const speed::StretchBound bound = speed::bound_stretch(path, sc.bench, c0, c1);
        if (bound.verdict != speed::BoundVerdict::bounded) continue;
        ++bounded;
        const double inside = dense_max(path, sc.bench, a, b, (b - a) / 400.0);
        EXPECT_LE(inside, bound.upper) << "on [" << a << ", " << b << "]";
    }
    EXPECT_GE(bounded, 30);
}

// Lemma C (speed_bound.hpp, item 5): behind a handle that ends a stretch on a spiral coiling in,
// at a radius rho of at least 1 / 0.76 times every link behind it, no handle moves faster than
// its front neighbour. Checked on the exact speeds of whole chains, on the plain spiral and on
// the turnaround's way in, at pitches down to where the spiral's inner turns are too tight.
TEST(MaxSpeedProof, NoHandleOutrunsItsFrontBehindACalmHandle) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> pitch(0.3, 2.2), share(0.0, 1.0);
    int checked = 0;
    for (int trial = 0; trial < 40; ++trial) {
        Scenario sc;
        sc.path.pitch = pitch(rng);
        if (trial % 2 == 1) sc = turnaround_scenario(1.2 + 1.8 * share(rng), 1.6 + 0.6 * share(rng));
        const Simulation sim(sc);
        const ValidRange range = sim.valid_range();
        const double lo = std::max(range.from, -300.0), hi = std::min(range.to, 400.0);
        const double t = lo + share(rng) * (hi - lo);
        const Frame f = sim.frame(t);
        const Path& path = sim.path();
        for (size_t j = 0; j + 1 < f.handles.size(); ++j) {
            const Spiral* spiral = path.coil_in_spiral(f.handles[j].place);
            const double longest = std::max(sc.bench.link_after(static_cast<int>(j)), sc.bench.link_length(2));
            if (!(spiral && f.handles[j].speed > 0.0 && longest <= 0.76 * spiral->b() * f.handles[j].place.u)) continue;
            for (size_t i = j; i + 1 < f.handles.size(); ++i) {
                ASSERT_GT(f.handles[i + 1].speed, 0.0) << "handle " << i + 1 << ", trial " << trial;
                ASSERT_LE(f.handles[i + 1].speed, f.handles[i].speed * (1.0 + 1e-12)) << "handle " << i + 1 << ", trial " << trial;
            }
            ++checked;
            break;
        }
    }
    EXPECT_GE(checked, 30);
}

// The bound stops at a calm tail when not asked for every handle's arc: no higher than the
// whole chain's bound (the same links up to there), and still above every speed inside the
// stretch (dense samples of every handle); before the turn, where the whole chain coils in,
// it is the head's speed exactly.
TEST(MaxSpeedProof, ACalmTailStopsTheBoundAndLosesNothing) {
    const Scenario sc = turnaround_scenario();
    const TurnaroundPath path(design_s_curve(sc));
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> where(-100.0, 99.5), width(0.02, 0.3);
    Frame f0, f1;
    speed::ChainFacts c0, c1;
    std::vector<speed::HandleArc> arcs;
    int before_turn = 0;
    for (int trial = 0; trial < 40; ++trial) {
        const double a = where(rng), b = a + width(rng);
        facts_at(path, sc.bench, a, f0, c0);
        facts_at(path, sc.bench, b, f1, c1);
        const speed::StretchBound calm = speed::bound_stretch(path, sc.bench, c0, c1);
        const speed::StretchBound whole = speed::bound_stretch(path, sc.bench, c0, c1, &arcs);
        if (whole.verdict != speed::BoundVerdict::bounded) continue;
        ASSERT_EQ(calm.verdict, speed::BoundVerdict::bounded);
        EXPECT_LE(calm.upper, whole.upper) << "on [" << a << ", " << b << "]";
        EXPECT_LE(dense_max(path, sc.bench, a, b, (b - a) / 100.0), calm.upper) << "on [" << a << ", " << b << "]";
        if (f1.handles[0].place.piece == 0) {
            ++before_turn;
            EXPECT_EQ(calm.upper, 1.0) << "on [" << a << ", " << b << "]";
            continue;
        }
        // Chains cut short (as Q5's scan cuts them): cut after the calm handle, the same bound;
        // cut before it, none (the handles behind are bounded by nothing).
        const size_t calm_handle = speed::first_calm_handle(path, sc.bench, f1);
        ASSERT_LT(calm_handle, f1.handles.size()) << "on [" << a << ", " << b << "]";
        const auto cut = [&](size_t handles) {
            facts_at(path, sc.bench, a, f0, c0, static_cast<int>(handles));
            facts_at(path, sc.bench, b, f1, c1, static_cast<int>(handles));
            return speed::bound_stretch(path, sc.bench, c0, c1);
        };
        const speed::StretchBound after = cut(calm_handle + 2);
        ASSERT_EQ(after.verdict, calm.verdict) << "on [" << a << ", " << b << "]";
        EXPECT_EQ(after.upper, calm.upper) << "on [" << a << ", " << b << "]";
        EXPECT_EQ(cut(calm_handle).verdict, speed::BoundVerdict::not_monotone) << "on [" << a << ", " << b << "]";
        // Asked for the arcs (a contact search's leading benches), the handles given are bounded.
        EXPECT_EQ(speed::bound_stretch(path, sc.bench, c0, c1, &arcs).verdict, speed::BoundVerdict::bounded)
            << "on [" << a << ", " << b << "]";
        EXPECT_EQ(arcs.size(), calm_handle) << "on [" << a << ", " << b << "]";
    }
    EXPECT_GE(before_turn, 10);
}
