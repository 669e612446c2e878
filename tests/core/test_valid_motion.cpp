// The end of the valid motion (find_jam, Simulation::valid_range) against an independent check:
// the chain sampled densely along the head's travel, the first pair of samples between which a
// handle jumps (moves farther than any motion could in that time), then bisection of that
// continuity criterion. It shares nothing with the search but the chain solver (the model).
#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "core/make_path.hpp"
#include "dragon/chain.hpp"
#include "dragon/turnaround.hpp"
#include "dragon/valid_motion.hpp"

using namespace dragon;

namespace {

// A handle moving this far between two compared frames has jumped: within the sample spacing
// below, the fastest real motion in these runs (a rear handle racing as its root vanishes,
// ~0.28 / sqrt(time left) m/s) covers under a tenth of it.
constexpr double kJump = 0.2;
// Sample spacing, m of head travel.
constexpr double kSpacing = 0.05;

struct Jump {
    double head_arc;   // the last position known continuous, to 1e-11 m
    int handle;        // the first handle that jumps
    bool ahead;        // it jumps ahead along the path (to a nearer root)
};

// The first handle whose position moved more than kJump from a to b, or -1.
int jumped(const Frame& a, const Frame& b) {
    for (size_t i = 0; i < a.handles.size(); ++i)
        if (distance(a.handles[i].pos, b.handles[i].pos) > kJump) return static_cast<int>(i);
    return -1;
}

std::optional<Jump> first_jump(const Path& path, const BenchSpec& spec, double s0, double s1) {
    Frame last, next;
    solve_chain(path, spec, s0, 1.0, last);
    const double dir = s1 > s0 ? 1.0 : -1.0;
    const long samples = static_cast<long>(std::ceil(std::abs(s1 - s0) / kSpacing));
    for (long k = 1; k <= samples; ++k) {
        const double s = k == samples ? s1 : s0 + dir * k * kSpacing;
        solve_chain(path, spec, s, 1.0, next);
        if (jumped(last, next) < 0) {
            std::swap(last, next);
            continue;
        }
        // Bisection: lo continuous with the samples before it, hi past a jump from lo.
        double lo = last.head_arc, hi = s;
        Frame mid_frame;
        while (std::abs(hi - lo) > 1e-11) {
            const double mid = 0.5 * (lo + hi);
            solve_chain(path, spec, mid, 1.0, mid_frame);
            if (jumped(last, mid_frame) < 0) {
                lo = mid;
                std::swap(last, mid_frame);
            } else {
                hi = mid;
            }
        }
        solve_chain(path, spec, hi, 1.0, next);
        const int h = jumped(last, next);
        const double before = path.arc(last.handles[static_cast<size_t>(h)].place);
        const double after = path.arc(next.handles[static_cast<size_t>(h)].place);
        return Jump{lo, h, after > before};
    }
    return std::nullopt;
}

void expect_agree(const Path& path, const Scenario& s, double start_arc, double t_from, double t_to,
                  const std::string& what) {
    const std::optional<Jam> jam = find_jam(path, s.bench, start_arc, s.head_speed, t_from, t_to);
    const double s0 = start_arc + s.head_speed * t_from, s1 = start_arc + s.head_speed * t_to;
    const std::optional<Jump> jump = first_jump(path, s.bench, s0, s1);
    ASSERT_EQ(jam.has_value(), jump.has_value()) << what;
    if (!jam) return;
    EXPECT_NEAR(jam->head_arc, jump->head_arc, 1e-9 * s.head_speed) << what;
    EXPECT_NEAR(jam->time, (jump->head_arc - start_arc) / s.head_speed, 1e-9) << what;
    EXPECT_LE(jam->tolerance, 1e-9) << what;
    EXPECT_EQ(jam->handle, jump->handle) << what;
    // A nearer root pulls the rear handle ahead along the path; a vanishing one leaves it the
    // next root behind. Either way of travel, as the search goes; a Jam tells what happens as
    // time runs forward, the reverse of what a search going back sees.
    const JamKind seen = jump->ahead ? JamKind::nearer_root : JamKind::root_vanishes;
    const bool forward = s1 > s0;
    const JamKind reversed = seen == JamKind::nearer_root ? JamKind::root_vanishes : JamKind::nearer_root;
    EXPECT_EQ(jam->kind, forward ? seen : reversed) << what;
    EXPECT_EQ(jam->ahead, forward) << what;
}

}  // namespace

TEST(ValidMotion, TheContestSpiralEndsWhereTheSamplesJump) {
    const Scenario s;
    const PathBuild b = make_path(s);
    const Simulation sim(s);
    expect_agree(*b.path, s, b.start_arc, 0.0, sim.end_time(), "contest spiral");
    // Handle 1's root vanishes: it races backwards (its speed has no bound) just before.
    const ValidRange r = sim.valid_range();
    ASSERT_TRUE(r.after);
    EXPECT_EQ(r.after->handle, 1);
    EXPECT_EQ(r.after->kind, JamKind::root_vanishes);
    EXPECT_NEAR(r.to, 432.9179242, 1e-6);
    EXPECT_LT(sim.frame(r.to - 1e-6).handles[1].speed, -50.0);
}

TEST(ValidMotion, OtherSpiralsToo) {
    struct Case {
        double pitch, head, body, start_turn;
    };
    for (const Case c : {Case{0.9, 3.41, 2.2, 8.0}, Case{0.55, 1.2, 2.5, 10.0}, Case{1.7, 3.41, 2.2, 5.0},
                         Case{0.4, 2.0, 2.0, 20.0}}) {
        Scenario s;
        s.bench = {30, c.head, c.body, 0.3, 0.2};
        s.path.pitch = c.pitch;
        s.path.start_turn = c.start_turn;
        s.head_speed = 2.5;
        const PathBuild b = make_path(s);
        const Simulation sim(s);
        expect_agree(*b.path, s, b.start_arc, 0.0, sim.end_time(),
                     "pitch " + std::to_string(c.pitch) + " head " + std::to_string(c.head));
    }
}

TEST(ValidMotion, TurnaroundRatios) {
    // Ratios 2.5 and up end with a nearer root behind the head on the way through (handle 1
    // jumps); 0.25 jams on the first arc; 2, the contest's, is followed all the way.
    for (double ratio : {0.25, 2.0, 2.5, 3.0, 5.0}) {
        Scenario s;
        s.path.kind = PathKind::turnaround;
        s.path.arc_ratio = ratio;
        const PathBuild b = make_path(s);
        // Through the turn until the tail is far out on the coil-out spiral.
        expect_agree(*b.path, s, b.start_arc, -30.0, 420.0, "ratio " + std::to_string(ratio));
    }
}

TEST(ValidMotion, BackwardsFromInside) {
    // Started well inside the radius where coiling in ends, the dragon's chain is the nearest-
    // root one there; run back out, it meets the end of its valid motion from the other side.
    Scenario s;
    s.path.start_turn = 1.5;  // the head at radius 0.825 m
    const PathBuild b = make_path(s);
    const std::optional<Jam> out = find_jam(*b.path, s.bench, b.start_arc, 1.0, 0.0, -INFINITY);
    ASSERT_TRUE(out);
    EXPECT_LT(out->time, 0.0);
    expect_agree(*b.path, s, b.start_arc, 0.0, out->time - 5.0, "backwards");
    const Simulation sim(s);
    EXPECT_EQ(sim.valid_range().from, out->time);
    EXPECT_THROW(sim.frame(out->time - 1e-3), InputError);
    EXPECT_NO_THROW(sim.frame(out->time + 1e-3));
}

TEST(ValidMotion, SimulationRefusesMomentsPastTheJam) {
    Scenario s;
    s.path.kind = PathKind::turnaround;
    s.path.arc_ratio = 3.0;
    const Simulation sim(s);
    const ValidRange r = sim.valid_range();
    ASSERT_TRUE(r.after);
    EXPECT_NEAR(r.to, 15.14771268, 1e-7);
    EXPECT_EQ(r.from, -INFINITY);
    EXPECT_NO_THROW(sim.frame(r.to));
    try {
        sim.frame(15.1478);
        ADD_FAILURE() << "a moment past the jam was accepted";
    } catch (const InputError& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find(fmt::format("until t = {:.9f} s", r.to)), std::string::npos) << m;
        EXPECT_NE(m.find("handle 1"), std::string::npos) << m;
    }
    // An analysis range reaching past it is cut there, and says so.
    const Simulation::Span span = sim.clip_to_valid(-100.0, 100.0, Key::from, Key::to);
    EXPECT_EQ(span.to, r.to);
    ASSERT_TRUE(span.jam);
    EXPECT_THROW(sim.clip_to_valid(20.0, 30.0, Key::from, Key::to), InputError);
    // Copies share what was found.
    const Simulation copy = sim;
    EXPECT_EQ(copy.valid_range().to, r.to);
}

TEST(ValidMotion, GentleScenariosNeverJam) {
    // A short chain of short benches on a wide spiral: certified to the centre's doorstep.
    Scenario s;
    s.bench = {5, 0.8, 0.8, 0.2, 0.1};
    s.path.pitch = 2.0;
    const Simulation sim(s);
    const ValidRange r = sim.valid_range();
    const PathBuild b = make_path(s);
    const std::optional<Jump> jump = first_jump(*b.path, s.bench, b.start_arc, b.start_arc + sim.end_time());
    EXPECT_FALSE(r.after.has_value());
    EXPECT_FALSE(jump.has_value());
    EXPECT_EQ(r.to, sim.end_time());
    EXPECT_NO_THROW(sim.frame(r.to));
}

TEST(ValidMotion, ATurnWiderThanEveryLinkIsFollowedForEver) {
    // A turning space of radius 20 m bends no link near its limit anywhere: the path is calm
    // everywhere, the walk has nothing to do in either direction, and the dense scan agrees.
    Scenario s;
    s.path.kind = PathKind::turnaround;
    s.path.turn_radius = 20.0;
    const PathBuild b = make_path(s);
    EXPECT_FALSE(find_jam(*b.path, s.bench, b.start_arc, 1.0, -INFINITY, INFINITY));
    EXPECT_FALSE(find_jam(*b.path, s.bench, b.start_arc, 1.0, 0.0, -INFINITY));
    expect_agree(*b.path, s, b.start_arc, -100.0, 100.0, "turn radius 20");
}
