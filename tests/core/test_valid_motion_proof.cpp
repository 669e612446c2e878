// The valid-motion walk's proved steps (docs/methods.md, section 4.1; core/motion_proof.hpp)
// against independent checks: each link's health computed here by dense samples of the path
// (min over the link of max(d - R, (d/2) dR/dsigma), positive exactly while the rear handle's
// root is simple and the nearest), and handles that jump between close samples of the head's
// travel. Nothing here comes from the program's own output.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "core/jam_walk.hpp"
#include "core/make_path.hpp"
#include "dragon/chain.hpp"
#include "dragon/valid_motion.hpp"

using namespace dragon;

namespace {

// Samples of the path between a link's handles for its health: the health's slope along the
// path is at most 1 + (d/2) |curvature| < 3 m/m on these paths, so 4000 samples over a link of
// a few metres see it to within ~2e-3 m (the rear handle itself, where a vanishing root's
// health is least, is always one).
constexpr int kHealthSamples = 4000;

// Link k's health at the chain `f` (head speed 1), computed from the path alone.
double health(const Path& path, const Frame& f, size_t k, double d, int samples = kHealthSamples) {
    const Vec2 q = f.handles[k].pos;
    const double s_rear = path.arc(f.handles[k + 1].place), s_front = path.arc(f.handles[k].place);
    double least = INFINITY;
    for (int j = 0; j <= samples; ++j) {
        const Located p = path.at_arc(s_rear + (s_front - s_rear) * j / samples);
        const Vec2 w = q - p.pos;
        const double r = norm(w);
        const double slope = r > 0.0 ? dot(w, p.tangent) / r : 1.0;  // dR / dsigma, sigma the arc back from the front
        least = std::min(least, std::max(d - r, 0.5 * d * slope));
    }
    return least;
}

// The least health over every link of the chain at head arc s (coarser samples: a few hundred
// per link see a health of more than ~2e-2 m).
double least_health(const Path& path, const BenchSpec& spec, double s) {
    Frame f;
    solve_chain(path, spec, s, 1.0, f);
    double least = INFINITY;
    for (size_t k = 0; k + 1 < f.handles.size(); ++k)
        least = std::min(least, health(path, f, k, spec.link_after(static_cast<int>(k)), 400));
    return least;
}

// The largest distance any handle moves between the chains at head arcs a and b.
double largest_move(const Path& path, const BenchSpec& spec, double a, double b) {
    Frame fa, fb;
    solve_chain(path, spec, a, 1.0, fa);
    solve_chain(path, spec, b, 1.0, fb);
    double most = 0.0;
    for (size_t i = 0; i < fa.handles.size(); ++i) most = std::max(most, distance(fa.handles[i].pos, fb.handles[i].pos));
    return most;
}

struct Walked {
    std::vector<jam::WalkOptions::Step> steps;
    std::optional<jam::Found> found;
    JamSearchStats stats;
};

Walked walk(const Path& path, const BenchSpec& spec, double from, double dir, double end, jam::WalkOptions options = {}) {
    Walked w;
    options.log = &w.steps;
    jam::Walk walker(path, spec, from, dir, end, options);
    walker.advance(end);
    w.found = walker.found();
    w.stats = walker.stats();
    return w;
}

// The largest turning between a link's handles in the chain at head arc s.
double largest_link_turning(const Path& path, const BenchSpec& spec, double s) {
    Frame f;
    solve_chain(path, spec, s, 1.0, f);
    double most = 0.0;
    for (size_t k = 0; k + 1 < f.handles.size(); ++k) most = std::max(most, path.turning(f.handles[k + 1].place, f.handles[k].place));
    return most;
}

// Links turning by less than this between their handles are the walk's gentle ones (link_watch.hpp).
constexpr double kGentle = 1.2;

}  // namespace

// The walk asked to prove every step (JamSearchOptions::prove).
jam::WalkOptions proving() {
    jam::WalkOptions o;
    o.prove_health = o.prove_backing = true;
    return o;
}

// The first step a walk left unproved starts where some link turns too far for the turning proof.
void expect_first_unproved_turns(const Path& path, const BenchSpec& spec, const Walked& w) {
    for (const auto& st : w.steps) {
        if (st.proved) continue;
        EXPECT_GE(largest_link_turning(path, spec, st.from), kGentle) << st.from;
        return;
    }
}

TEST(ValidMotionProof, TheContestWalksProveTheirSteps) {
    const Scenario s;
    const PathBuild b = make_path(s);
    // The spiral, by default: the walk starts where the path stops being calm for the head's link
    // (proved: section 4.1's Proposition 2), and there the head's link already turns by more than
    // 1.2 rad: every step rests on the rate check.
    {
        const Walked w = walk(*b.path, s.bench, b.start_arc, 1.0, b.path->s_max());
        ASSERT_TRUE(w.found);
        EXPECT_EQ(w.stats.proved_steps, 0);
        EXPECT_EQ(w.stats.unproved_steps, static_cast<int>(w.steps.size()));
        expect_first_unproved_turns(*b.path, s.bench, w);
        ASSERT_FALSE(w.steps.empty());
        EXPECT_EQ(w.found->proved, w.steps.front().from);
    }
    // Asked to prove them: by the head link's health, to within 1e-6 m of the jam.
    {
        const Walked w = walk(*b.path, s.bench, b.start_arc, 1.0, b.path->s_max(), proving());
        ASSERT_TRUE(w.found);
        EXPECT_GT(w.stats.proved_steps, 100);
        EXPECT_LE(w.found->proved, w.found->valid);
        EXPECT_LT(w.found->valid - w.found->proved, 1e-6);
        EXPECT_EQ(w.stats.proved_steps + w.stats.unproved_steps, static_cast<int>(w.steps.size()));
    }
    // The turnaround at the contest's ratio, followed all the way through: by default its steps are
    // proved up to the S-curve's arcs, where the head's link turns by more than pi/2; asked to,
    // every step is proved.
    Scenario t;
    t.path.kind = PathKind::turnaround;
    const PathBuild tb = make_path(t);
    {
        const Walked w = walk(*tb.path, t.bench, tb.start_arc - 30.0, 1.0, tb.start_arc + 400.0);
        EXPECT_FALSE(w.found);
        EXPECT_GT(w.stats.proved_steps, 0);
        EXPECT_GT(w.stats.unproved_steps, 0);
        expect_first_unproved_turns(*tb.path, t.bench, w);
    }
    {
        jam::WalkOptions o = proving();
        std::vector<jam::WalkOptions::Step> steps;
        o.log = &steps;
        jam::Walk walker(*tb.path, t.bench, tb.start_arc - 30.0, 1.0, tb.start_arc + 400.0, o);
        walker.advance(tb.start_arc + 400.0);
        EXPECT_FALSE(walker.found());
        EXPECT_GT(walker.stats().proved_steps, 0);
        EXPECT_EQ(walker.stats().unproved_steps, 0);
        EXPECT_EQ(walker.proved(), INFINITY);
    }
}

TEST(ValidMotionProof, TheProofDoesNotProveStepsTheRatesMadeTooLong) {
    // Steps a thousand times longer than the rates allow (up to the walk's 2 m): on the contest's
    // spiral the check at each step's end then accepts a step with the jam inside and the walk
    // runs on past it. The proof proves none of the steps with the jam inside.
    const Scenario s;
    const PathBuild b = make_path(s);
    const Walked truth = walk(*b.path, s.bench, b.start_arc, 1.0, b.path->s_max());
    ASSERT_TRUE(truth.found);
    const double jam = truth.found->valid;
    jam::WalkOptions sloppy;
    sloppy.step_scale = 1000.0;
    sloppy.prove = false;
    const Walked blind = walk(*b.path, s.bench, b.start_arc, 1.0, b.path->s_max(), sloppy);
    // The end check alone accepted a step across the jam (it is then missed, or found late).
    bool across = false;
    for (const auto& st : blind.steps) across = across || (st.from < jam && st.to > jam);
    EXPECT_TRUE(across);
    EXPECT_EQ(blind.stats.proved_steps, 0);
    // With the proof, every proved step is clear of the jam (and of the continuity scan's jumps).
    jam::WalkOptions asked = proving();
    asked.step_scale = sloppy.step_scale;
    const Walked proved = walk(*b.path, s.bench, b.start_arc, 1.0, b.path->s_max(), asked);
    EXPECT_GT(proved.stats.proved_steps, 0);
    for (const auto& st : proved.steps) {
        if (!st.proved) continue;
        EXPECT_FALSE(st.from < jam + 1e-9 && st.to > jam - 1e-9) << st.from << " " << st.to;
    }
}

TEST(ValidMotionProof, TheJamAgreesWithADenseScanOfTheHealth) {
    // The contest's spiral (handle 1's root vanishes) and a turnaround whose S-curve makes
    // handle 1 jump to a nearer root: up to 1e-4 m of head travel before the jam every link's
    // health is positive and no handle jumps; across the jam, 1e-4 m either side, one does.
    std::vector<Scenario> cases(2);
    cases[1].path.kind = PathKind::turnaround;
    cases[1].path.arc_ratio = 2.5;
    for (const Scenario& s : cases) {
        const PathBuild b = make_path(s);
        const Walked w = walk(*b.path, s.bench, b.start_arc - (s.path.kind == PathKind::turnaround ? 30.0 : 0.0), 1.0,
                              b.path->s_max() < INFINITY ? b.path->s_max() : b.start_arc + 420.0);
        ASSERT_TRUE(w.found);
        const double jam = w.found->valid;
        EXPECT_LE(w.found->proved, jam);
        const BenchSpec& spec = s.bench;
        Frame f;
        const size_t k = static_cast<size_t>(w.found->link);
        double last = jam - 0.05;
        for (double x = jam - 0.05; x <= jam - 1e-4; x += 1e-4) {
            solve_chain(*b.path, spec, x, 1.0, f);
            EXPECT_GT(health(*b.path, f, k, spec.link_after(static_cast<int>(k))), 0.0) << x;
            EXPECT_LT(largest_move(*b.path, spec, last, x), 0.05) << x;
            last = x;
        }
        EXPECT_GT(largest_move(*b.path, spec, jam - 1e-4, w.found->past + 1e-4), 0.2);
    }
}

TEST(ValidMotionProof, ProvedStepsAreJamFreeInside) {
    // Random spirals and turnarounds (seeded): inside every step the walk proved, the chain
    // sampled 16 times has no handle jumping between samples, and every 4th sample every link
    // healthy. Some walks prove nothing (their first step already wraps a link round a tight
    // turn, and is halved only a few times); together they prove dozens of steps.
    std::mt19937 rng(20261127);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int checked = 0;
    for (int trial = 0; trial < 6; ++trial) {
        Scenario s;
        s.bench = {20, 2.0 + 1.6 * unit(rng), 1.4 + 0.8 * unit(rng), 0.3, 0.2};
        if (trial % 2 == 0) {
            s.path.pitch = 0.45 + 0.5 * unit(rng);
            s.path.start_turn = 6.0 + 4.0 * unit(rng);
        } else {
            s.path.kind = PathKind::turnaround;
            s.path.arc_ratio = 0.5 + 2.5 * unit(rng);
        }
        const PathBuild b = make_path(s);
        const double from = s.path.kind == PathKind::turnaround ? b.start_arc - 20.0 : b.start_arc;
        const double end = b.path->s_max() < INFINITY ? b.path->s_max() : from + 80.0;
        const Walked w = walk(*b.path, s.bench, from, 1.0, end, proving());
        for (const auto& st : w.steps) {
            if (!st.proved) continue;
            ++checked;
            constexpr int kInside = 16;
            double last = st.from;
            for (int j = 1; j <= kInside; ++j) {
                const double x = st.from + (st.to - st.from) * j / kInside;
                if (j % 4 == 0) {
                    EXPECT_GT(least_health(*b.path, s.bench, x), 0.0) << "trial " << trial << " at " << x;
                }
                EXPECT_LT(largest_move(*b.path, s.bench, last, x), 0.2) << "trial " << trial << " at " << x;
                last = x;
            }
        }
    }
    EXPECT_GT(checked, 20);
}

// A link whose calm certificate outlasts its turning's was checked with the turning's margin
// over the calm certificate's step: the turning outgrew that margin at every step length, and
// the walk crept on by the checks' rounding allowance until it ran out of evaluations (found by
// tests/fuzz/fuzz_contact on this dragon, starting 4.55 m into the turn). With or without the
// proof, the walk now takes the calm certificate's steps and checks them as calm ones.
TEST(ValidMotionProof, ALinkLeavingCalmPathDoesNotStallTheWalk) {
    Scenario s;
    s.path.kind = PathKind::turnaround;
    s.bench.bench_count = 17;
    s.bench.head_length = 3.096199355321398;
    s.bench.body_length = 2.4890524508262222;
    s.bench.width = 0.26554956211271774;
    s.bench.hole_offset = 0.21086981793608681;
    s.path.turn_radius = 2.8472625817459578;
    s.path.turn_pitch = 1.7170286151561698;
    s.path.arc_ratio = 1.3754580207288734;
    const PathBuild b = make_path(s);
    const double from = b.start_arc + 4.5531204147191175, to = b.start_arc + 9.5531204147191175;
    for (const bool prove : {false, true}) {
        const Walked w = walk(*b.path, s.bench, from, 1.0, to, prove ? proving() : jam::WalkOptions{});
        EXPECT_LT(w.stats.evaluations, 2000) << prove;
        EXPECT_LT(w.stats.retreats, 100) << prove;
        ASSERT_FALSE(w.steps.empty());
        EXPECT_EQ(w.steps.back().to, to) << prove;
        // Every step the walk took, the chain moves continuously: no handle moves farther than
        // twice the head's travel between its ends (a handle that jumped to another root would).
        for (const auto& st : w.steps) EXPECT_LE(largest_move(*b.path, s.bench, st.from, st.to), 2.0 * (st.to - st.from) + 1e-9);
    }
}
