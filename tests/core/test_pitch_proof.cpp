// The minimum pitch's proof (core/pitch_proof.hpp): what it proves checked against runs of the
// dragon at pitches it never ran, against dense samples inside its cells, and against ranges
// claimed feasible that hold a collision window narrower than the grid.
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "core/chain_front.hpp"
#include "core/pitch_proof.hpp"
#include "core/shape_rates.hpp"
#include "core/swept_proof.hpp"
#include "dragon/analyses.hpp"
#include "dragon/chain.hpp"
#include "dragon/collision.hpp"
#include "dragon/constants.hpp"
#include "dragon/path.hpp"

using namespace dragon;

namespace {

// The search's options with a 1 cm pitch grid (the cut is then narrowed as always).
MinPitchOptions coarse_grid() {
    MinPitchOptions o;
    o.grid = 0.01;
    return o;
}

// Every handle's angle, and the whole chain, on r = b theta with the head at radius r0.
std::vector<double> angles_at(const BenchSpec& spec, double r0, double b) {
    const Spiral spiral(kTwoPi * b);
    std::vector<double> theta;
    EXPECT_TRUE(solve_spiral_chain_angles(spiral, spec, spiral.arc({0, r0 / b}), theta));
    return theta;
}
Frame chain_at(const BenchSpec& spec, double r0, double b) {
    const Spiral spiral(kTwoPi * b);
    Frame f;
    solve_chain(spiral, spec, spiral.arc({0, r0 / b}), 1.0, f);
    return f;
}

double total_width(const std::vector<PitchInterval>& v) {
    double w = 0.0;
    for (const PitchInterval& i : v) w += i.hi - i.lo;
    return w;
}

// Whether the run to the boundary at `pitch` touches (a run of the search, independent of the proof).
bool collides(double pitch) {
    const BoundaryRun run = run_to_boundary(Scenario{}, pitch);
    return run.contact.has_value() || run.jam.has_value();
}

}  // namespace

// Proposition P2 checked by the chain solver alone: inside a cell every handle's polar offset
// from the head and every link's span lie between their values at the two corners.
TEST(PitchProof, ACellsCornersBoundEveryChainInsideIt) {
    const BenchSpec spec;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int cell = 0; cell < 6; ++cell) {
        const double p_lo = 0.45 + 0.1 * unit(rng), p_hi = p_lo + 2e-3 * unit(rng);
        const double r_hi = 4.6 + 3.0 * unit(rng), r_lo = r_hi - 0.05 * unit(rng);
        const double b_lo = p_lo / kTwoPi, b_hi = p_hi / kTwoPi;
        const std::vector<double> a = angles_at(spec, r_hi, b_hi), z = angles_at(spec, r_lo, b_lo);
        for (int k = 0; k < 20; ++k) {
            const double r0 = r_lo + (r_hi - r_lo) * unit(rng), b = b_lo + (b_hi - b_lo) * unit(rng);
            const std::vector<double> t = angles_at(spec, r0, b);
            for (size_t i = 1; i < t.size(); ++i) {
                const double D = t[i] - t[0], span = t[i] - t[i - 1];
                EXPECT_GE(D, (a[i] - a[0]) - 1e-12) << "cell " << cell << " handle " << i;
                EXPECT_LE(D, (z[i] - z[0]) + 1e-12) << "cell " << cell << " handle " << i;
                EXPECT_GE(span, (a[i] - a[i - 1]) - 1e-12);
                EXPECT_LE(span, (z[i] - z[i - 1]) + 1e-12);
                EXPECT_GE(b * t[i], b_lo * z[i] - 1e-12);  // radii: least at (r_lo, b_lo)
                EXPECT_LE(b * t[i], b_hi * a[i] + 1e-12);
            }
        }
    }
}

// A proved cell holds no contact anywhere inside it (dense samples, every non-adjacent pair);
// a cell holding a pitch that touches there is not proved.
TEST(PitchProof, AProvedCellHoldsNoContactAndATouchingOneIsNotProved) {
    const BenchSpec spec;
    const MinPitch m = min_pitch(Scenario{}, 0.44, 0.46, coarse_grid());
    const double cut = m.pitch;  // the least feasible pitch, to 1e-9 m
    ASSERT_TRUE(std::isfinite(cut));
    // The pair's closest approach at pitches just above the cut: the radius where the clearance
    // is least, from a scan of the run (clearance of the whole chain).
    const double b = (cut + 1e-4) / kTwoPi;
    double r_star = 0.0, least = INFINITY;
    for (double r0 = 4.5; r0 < 4.7; r0 += 5e-4) {
        const double c = clearance(chain_at(spec, r0, b)).distance;
        if (c < least) least = c, r_star = r0;
    }
    ASSERT_GT(least, 0.0);
    contact::SweptWorkspace ws;
    int proved = 0;
    for (const double width : {1e-3, 1e-4, 1e-5}) {
        const double r_hi = r_star + width, r_lo = r_star - width;
        const double b_lo = (cut + 1e-4) / kTwoPi, b_hi = (cut + 1.1e-4) / kTwoPi;
        const std::vector<double> ta = angles_at(spec, r_hi, b_hi), tb = angles_at(spec, r_lo, b_lo);
        const size_t watched = contact::spiral_cell_benches(spec, ta, tb, b_lo, b_hi, ws);
        Frame fa, fb;
        const Spiral sa(kTwoPi * b_hi), sb(kTwoPi * b_lo);
        solve_chain_front(sa, spec, sa.arc({0, r_hi / b_hi}), 1.0, static_cast<int>(watched) + 1, fa);
        solve_chain_front(sb, spec, sb.arc({0, r_lo / b_lo}), 1.0, static_cast<int>(watched) + 1, fb);
        const std::vector<contact::SpiralCorner> corners{
            {r_lo / b_lo, b_lo}, {r_lo / b_hi, b_hi}, {r_hi / b_lo, b_lo}, {r_hi / b_hi, b_hi}};
        const contact::StepProof p = contact::prove_spiral_cell(spec, fa, fb, corners, ws);
        if (p.verdict != contact::StepVerdict::proved) continue;
        ++proved;
        for (int i = 0; i <= 10; ++i)
            for (int j = 0; j <= 10; ++j) {
                const double r0 = r_lo + (r_hi - r_lo) * i / 10.0, bb = b_lo + (b_hi - b_lo) * j / 10.0;
                const double c = clearance_all_pairs(chain_at(spec, r0, bb)).distance;
                EXPECT_GE(c, p.least_gap - 1e-12) << "r0 " << r0 << " b " << bb;
            }
    }
    EXPECT_GT(proved, 0) << "no cell around the closest approach was proved";
    // Pitches just below the cut touch there: a cell holding them is not proved.
    const double r_hi = r_star + 1e-3, r_lo = r_star - 1e-3;
    const double b_lo = (cut - 2e-5) / kTwoPi, b_hi = (cut - 1e-5) / kTwoPi;
    ASSERT_TRUE(collides(cut - 1.5e-5));
    const std::vector<double> ta = angles_at(spec, r_hi, b_hi), tb = angles_at(spec, r_lo, b_lo);
    const size_t watched = contact::spiral_cell_benches(spec, ta, tb, b_lo, b_hi, ws);
    const Frame fa = chain_at(spec, r_hi, b_hi), fb = chain_at(spec, r_lo, b_lo);
    (void)watched;
    const std::vector<contact::SpiralCorner> corners{
        {r_lo / b_lo, b_lo}, {r_lo / b_hi, b_hi}, {r_hi / b_lo, b_lo}, {r_hi / b_hi, b_hi}};
    EXPECT_NE(contact::prove_spiral_cell(spec, fa, fb, corners, ws).verdict, contact::StepVerdict::proved);
}

// Proposition P5 checked by finite differences: inside a cell every handle's speed and
// acceleration in the head's turned frame, as the head's radius changes at a fixed pitch, stay
// within the bounds; and the bounds are close (the largest handle's within a few per cent).
TEST(ShapeRates, BoundEveryHandlesRatesInsideTheCell) {
    const BenchSpec spec;
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    // A handle's place in the frame turned with the head: radius b theta, angle theta - theta_0.
    const auto place = [](const Frame& f, size_t m, double b) {
        const double D = f.handles[m].place.u - f.handles[0].place.u;
        return Vec2{b * f.handles[m].place.u * std::cos(D), b * f.handles[m].place.u * std::sin(D)};
    };
    for (int cell = 0; cell < 5; ++cell) {
        const double p_lo = 0.45 + 0.1 * unit(rng), p_hi = p_lo + 1e-3 * unit(rng);
        const double r_hi = 4.6 + 3.0 * unit(rng), r_lo = r_hi - 0.02 * unit(rng);
        const double b_lo = p_lo / kTwoPi, b_hi = p_hi / kTwoPi;
        std::vector<double> speed, accel;
        ASSERT_TRUE(contact::shape_rate_bounds(chain_at(spec, r_hi, b_hi), chain_at(spec, r_lo, b_lo), b_lo, b_hi, speed, accel));
        double closest = 0.0;  // the largest ratio of a difference quotient to its bound
        for (int k = 0; k < 6; ++k) {
            const double r0 = r_lo + (r_hi - r_lo) * unit(rng), b = b_lo + (b_hi - b_lo) * unit(rng);
            constexpr double e = 1e-4;  // m of head radius: the quotients' error is ~1e-7 of them
            const Frame before = chain_at(spec, r0 - e, b), at = chain_at(spec, r0, b), after = chain_at(spec, r0 + e, b);
            ASSERT_EQ(speed.size(), at.handles.size());
            for (size_t m = 1; m < at.handles.size(); ++m) {
                const Vec2 rate = (place(after, m, b) - place(before, m, b)) / (2.0 * e);
                const Vec2 bend = (place(after, m, b) - 2.0 * place(at, m, b) + place(before, m, b)) / (e * e);
                EXPECT_LE(rate.norm(), speed[m] * (1.0 + 1e-6)) << "cell " << cell << " handle " << m;
                EXPECT_LE(bend.norm(), accel[m] * (1.0 + 1e-5) + 1e-6) << "cell " << cell << " handle " << m;
                closest = std::max(closest, bend.norm() / accel[m]);
            }
        }
        EXPECT_GT(closest, 0.9) << "cell " << cell << ": the bounds are loose";
    }
}

// The second-order cell (Proposition P6): a proved cell around the closest approach of pitches
// just above the cut holds no contact anywhere inside it (dense samples, every non-adjacent
// pair), where the first order cannot prove a cell of the same size; a cell holding pitches that
// touch there is not proved.
TEST(PitchProof, ASecondOrderCellProvesWhatTheFirstOrderCannotAndNoContact) {
    const BenchSpec spec;
    const MinPitch m = min_pitch(Scenario{}, 0.44, 0.46, coarse_grid());
    const double cut = m.pitch;
    ASSERT_TRUE(std::isfinite(cut));
    const double p_lo = cut + 1e-6, p_hi = cut + 1.1e-6;
    const double b_lo = p_lo / kTwoPi, b_hi = p_hi / kTwoPi;
    double r_star = 0.0, least = INFINITY;
    for (double r0 = 4.5; r0 < 4.7; r0 += 1e-4) {
        const double c = clearance(chain_at(spec, r0, b_lo)).distance;
        if (c < least) least = c, r_star = r0;
    }
    ASSERT_GT(least, 0.0);
    ASSERT_LT(least, 1e-5);  // a grazing pass: the pair's closest approach a few micrometres
    contact::SweptWorkspace ws;
    const auto prove = [&](double r_lo, double r_hi, double bl, double bh, bool second) {
        const std::vector<double> ta = angles_at(spec, r_hi, bh), tb = angles_at(spec, r_lo, bl);
        const size_t watched = contact::spiral_cell_benches(spec, ta, tb, bl, bh, ws);
        Frame f[4];  // (r_lo, b_lo), (r_lo, b_hi), (r_hi, b_lo), (r_hi, b_hi)
        for (int c = 0; c < 4; ++c) {
            const double r = c < 2 ? r_lo : r_hi, bb = c % 2 == 0 ? bl : bh;
            const Spiral sp(kTwoPi * bb);
            solve_chain_front(sp, spec, sp.arc({0, r / bb}), 1.0, static_cast<int>(watched) + 1, f[c]);
        }
        if (second) return contact::prove_spiral_cell_second_order(spec, {f[0], f[1], f[2], f[3], r_lo, r_hi, bl, bh}, ws);
        const std::vector<contact::SpiralCorner> corners{{r_lo / bl, bl}, {r_lo / bh, bh}, {r_hi / bl, bl}, {r_hi / bh, bh}};
        return contact::prove_spiral_cell(spec, f[3], f[0], corners, ws);
    };
    // A cell 0.2 mm of head radius across: the first order needs cells about a thousand times
    // shorter here (its looseness is about 3 times the cell's half width).
    const double r_lo = r_star - 1e-4, r_hi = r_star + 1e-4;
    const contact::StepProof second = prove(r_lo, r_hi, b_lo, b_hi, true);
    ASSERT_EQ(second.verdict, contact::StepVerdict::proved);
    EXPECT_NE(prove(r_lo, r_hi, b_lo, b_hi, false).verdict, contact::StepVerdict::proved);
    EXPECT_GT(second.least_gap, 0.0);
    for (int i = 0; i <= 20; ++i)
        for (int j = 0; j <= 4; ++j) {
            const double r0 = r_lo + (r_hi - r_lo) * i / 20.0, bb = b_lo + (b_hi - b_lo) * j / 4.0;
            const double c = clearance_all_pairs(chain_at(spec, r0, bb)).distance;
            EXPECT_GE(c, second.least_gap - 1e-12) << "r0 " << r0 << " b " << bb;
        }
    // Pitches just below the cut touch there: a cell holding them is not proved, however short.
    ASSERT_TRUE(collides(cut - 1.5e-6));
    for (const double half : {1e-4, 1e-5}) {
        double r_touch = 0.0, deepest = INFINITY;
        for (double r0 = r_star - 2e-3; r0 < r_star + 2e-3; r0 += 1e-5) {
            const double c = clearance(chain_at(spec, r0, (cut - 1.5e-6) / kTwoPi)).distance;
            if (c < deepest) deepest = c, r_touch = r0;
        }
        ASSERT_LT(deepest, 0.0);
        EXPECT_NE(prove(r_touch - half, r_touch + half, (cut - 2e-6) / kTwoPi, (cut - 1e-6) / kTwoPi, true).verdict,
                  contact::StepVerdict::proved);
    }
}

// The contest: the search's answer is proved feasible on its own, every pitch of the feasible
// interval but those within a few times the search's resolution above the cut, and every pitch
// below it but those within that resolution; runs at pitches the search never ran (spread
// geometrically from the cut) agree.
TEST(PitchProof, ProvesTheContestsFeasibleIntervalUpToTheCut) {
    ThreadPool pool(2);
    MinPitchOptions o;
    o.executor = &pool;
    o.prove = true;
    const MinPitch m = min_pitch(Scenario{}, 0.35, 0.55, o);
    ASSERT_TRUE(m.proof.has_value());
    const PitchProof& p = *m.proof;
    // The answer alone, then the rest of the interval from within a few nanometres of it.
    ASSERT_EQ(p.proved.size(), 2u);
    EXPECT_EQ(p.proved.front().lo, m.pitch);
    EXPECT_EQ(p.proved.front().hi, m.pitch);
    EXPECT_FALSE(collides(m.pitch));
    const PitchInterval& rest = p.proved.back();
    EXPECT_TRUE(rest.feasible);
    EXPECT_EQ(rest.hi, 0.55);
    EXPECT_GT(rest.lo, m.pitch);
    EXPECT_LT(rest.lo - m.pitch, 10 * tol::pitch);
    EXPECT_LT(total_width(p.unproved), 10 * tol::pitch);
    for (const PitchInterval& u : p.unproved) EXPECT_GE(u.lo, m.pitch);
    EXPECT_GT(p.least_gap, 0.0);
    EXPECT_GT(p.cells, 0);
    EXPECT_STREQ(p.method(), "enclosure cells, incomplete");
    for (double d = 1e-8; d < 0.1; d *= 3.7) {
        const double pitch = rest.lo + d;
        EXPECT_FALSE(collides(pitch)) << pitch;
    }
    // Below the cut every pitch is proved to collide but those within the search's resolution of
    // it, and runs at pitches the search never ran agree; so the least feasible pitch is
    // bracketed as closely as the search claims it, the answer its upper end.
    ASSERT_EQ(p.proved_colliding.size(), 1u);
    EXPECT_EQ(p.proved_colliding.front().lo, 0.35);
    EXPECT_LE(p.proved_colliding.front().hi, m.pitch);
    EXPECT_LT(m.pitch - p.proved_colliding.front().hi, tol::pitch);
    ASSERT_EQ(p.unproved_colliding.size(), 1u);
    EXPECT_EQ(p.unproved_colliding.front().lo, p.proved_colliding.front().hi);
    EXPECT_EQ(p.unproved_colliding.front().hi, m.pitch);
    for (double d = 1e-8; d < 0.1; d *= 3.7) {
        const double pitch = p.proved_colliding.front().hi - d;
        EXPECT_TRUE(collides(pitch)) << pitch;
    }
    EXPECT_EQ(p.least_lo, p.proved_colliding.front().hi);
    EXPECT_EQ(p.least_hi, m.pitch);
}

// Other dragons (random board widths, lengths and hole offsets): every proved interval agrees
// with runs at pitches the search never ran, spread geometrically from each cut (where the proofs
// are tightest) and at random inside.
TEST(PitchProof, OtherDragonsProvedIntervalsAgreeWithRuns) {
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    ThreadPool pool(2);
    int checked = 0;
    for (int dragon = 0; dragon < 3; ++dragon) {
        Scenario s;
        s.bench.width = 0.22 + 0.12 * unit(rng);
        s.bench.body_length = 1.9 + 0.5 * unit(rng);
        s.bench.head_length = s.bench.body_length + 0.8 + 0.8 * unit(rng);
        s.bench.hole_offset = 0.2 + 0.1 * unit(rng);
        MinPitchOptions o = coarse_grid();
        o.executor = &pool;
        o.prove = true;
        const MinPitch m = min_pitch(s, 0.35, 0.6, o);
        ASSERT_TRUE(m.proof.has_value());
        const PitchProof& p = *m.proof;
        const auto collides_at = [&](double pitch) {
            const BoundaryRun run = run_to_boundary(s, pitch);
            return run.contact.has_value() || run.jam.has_value();
        };
        const auto check = [&](const std::vector<PitchInterval>& v, bool colliding) {
            for (const PitchInterval& iv : v) {
                std::vector<double> pitches{iv.lo, iv.hi};
                for (double d = 1e-9; d < iv.hi - iv.lo; d *= 7.3) pitches.insert(pitches.end(), {iv.lo + d, iv.hi - d});
                for (int k = 0; k < 4; ++k) pitches.push_back(iv.lo + (iv.hi - iv.lo) * unit(rng));
                for (const double pitch : pitches) {
                    EXPECT_EQ(collides_at(pitch), colliding)
                        << "dragon " << dragon << " width " << s.bench.width << " pitch " << pitch << " in ["
                        << iv.lo << ", " << iv.hi << "] proved " << (colliding ? "colliding" : "feasible");
                    ++checked;
                }
            }
        };
        check(p.proved, false);
        check(p.proved_colliding, true);
        // The proofs reach their cuts: all but a few times the search's resolution is proved.
        EXPECT_LT(total_width(p.unproved) + total_width(p.unproved_colliding), 10 * tol::pitch) << "dragon " << dragon;
        EXPECT_FALSE(p.proved.empty() || p.proved_colliding.empty()) << "dragon " << dragon;
    }
    EXPECT_GT(checked, 100);
}

// A range claimed colliding that holds feasible pitches (the contest's cut inside it, and half a
// micrometre of feasible pitches above it; no cut is named, so a range whose middle pitch runs
// clear is not halved): no pitch at or above the cut is proved colliding, and the pitches well
// below it are.
TEST(PitchProof, NeverProvesFeasiblePitchesColliding) {
    const MinPitch m = min_pitch(Scenario{}, 0.44, 0.46, coarse_grid());
    const double cut = m.pitch;
    ASSERT_TRUE(std::isfinite(cut));
    ASSERT_FALSE(collides(cut + 2.5e-7));
    ThreadPool pool(2);
    const PitchProof p = prove_pitches(Scenario{}, {{0.448, cut + 5e-7, false}}, pool);
    ASSERT_FALSE(p.proved_colliding.empty());
    for (const PitchInterval& iv : p.proved_colliding) EXPECT_LE(iv.hi, cut) << "proved a feasible pitch colliding";
    EXPECT_EQ(p.proved_colliding.front().lo, 0.448);
    EXPECT_GT(p.proved_colliding.back().hi, cut - 1e-5);
    EXPECT_FALSE(p.unproved_colliding.empty());
    EXPECT_EQ(p.unproved_colliding.back().hi, cut + 5e-7);
}

// A range claimed feasible that holds a collision window narrower than the grid (the pitches
// just below the contest's cut, a micrometre of them, at its start; each range there is halved
// down to tol::pitch, so the cost grows with the width): the proof leaves the window unproved,
// proves no pitch that collides, and proves the rest from within a few nanometres of the cut.
TEST(PitchProof, NeverProvesAWindowOfCollisionInsideARangeClaimedFeasible) {
    const MinPitch m = min_pitch(Scenario{}, 0.44, 0.46, coarse_grid());
    const double cut = m.pitch;
    ASSERT_TRUE(std::isfinite(cut));
    const double window_lo = cut - 1e-6;
    ASSERT_TRUE(collides(window_lo));
    ASSERT_TRUE(collides(cut - 2e-9));
    ThreadPool pool(2);
    const PitchProof p = prove_pitches(Scenario{}, {{window_lo, 0.452, true}}, pool);
    ASSERT_FALSE(p.proved.empty());
    for (const PitchInterval& iv : p.proved) EXPECT_GE(iv.lo, cut - tol::pitch) << "proved a colliding pitch";
    ASSERT_FALSE(p.unproved.empty());
    EXPECT_EQ(p.unproved.front().lo, window_lo);
    EXPECT_GE(p.unproved.front().hi, cut - tol::pitch);
    // The rest of the range is proved.
    EXPECT_EQ(p.proved.back().hi, 0.452);
    EXPECT_LT(p.proved.front().lo - cut, 10 * tol::pitch);
}

// Runs that end in a jam give no contact to take a witness from (a turning space of radius 1 m:
// every pitch of [0.7, 0.8] m coils in without contact, but the dragon stops following the
// spiral before its head gets there): each part's range is left to the runs at once. Halving
// them went on without end (`dragon min-pitch --turn-radius 1 --lo 0.7 --hi 0.8 --grid 0.05
// --prove` ran for minutes).
TEST(PitchProof, RangesWhoseRunsJamAreLeftToTheRuns) {
    Scenario s;
    s.path.turn_radius = 1.0;
    ThreadPool pool(2);
    MinPitchOptions o;
    o.grid = 0.05;
    o.executor = &pool;
    o.prove = true;
    const MinPitch m = min_pitch(s, 0.7, 0.8, o);
    ASSERT_TRUE(m.above_range);
    ASSERT_TRUE(m.jam.has_value());
    for (const double p : {0.7, 0.7125, 0.75, 0.7875}) {
        const BoundaryRun run = run_to_boundary(s, p);
        EXPECT_TRUE(run.jam.has_value() && !run.contact.has_value()) << p;
    }
    ASSERT_TRUE(m.proof.has_value());
    const PitchProof& p = *m.proof;
    EXPECT_TRUE(p.proved_colliding.empty());
    ASSERT_EQ(p.unproved_colliding.size(), 1u);
    EXPECT_EQ(p.unproved_colliding.front().lo, 0.7);
    EXPECT_EQ(p.unproved_colliding.front().hi, 0.8);
    EXPECT_LE(p.pitch_ranges, 8);  // one per part: none halved
    EXPECT_STREQ(p.method(), "enclosure cells, incomplete");
}

// A range claimed colliding whose middle pitch runs clear, away from any cut, holds feasible
// pitches the search missed: it is left to the runs, not halved down to the finest width (each
// half a run). Here the whole of [0.46, 0.55] m is feasible, claimed colliding.
TEST(PitchProof, ARangeClaimedCollidingThatRunsClearIsLeftToTheRuns) {
    InlineExecutor serial;
    const PitchProof p = prove_pitches(Scenario{}, {{0.46, 0.55, false}}, serial);
    EXPECT_TRUE(p.proved_colliding.empty());
    ASSERT_EQ(p.unproved_colliding.size(), 1u);
    EXPECT_EQ(p.unproved_colliding.front().lo, 0.46);
    EXPECT_EQ(p.unproved_colliding.front().hi, 0.55);
    EXPECT_LE(p.pitch_ranges, 8);
    for (const double pitch : {0.46, 0.5, 0.55}) EXPECT_TRUE(run_to_boundary(Scenario{}, pitch).feasible()) << pitch;
}
