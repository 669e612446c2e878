// Storyboards resolved against their runs: frame counts, moments, events, the valid motion and
// transitions, each expectation worked out here from the storyboard's numbers.
#include <cmath>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "dragon/analyses.hpp"
#include "dragon/film.hpp"

using namespace dragon;

namespace {

const std::string assets = std::string(DRAGON_SOURCE_DIR) + "/assets";

Storyboard parse(const std::string& text) { return parse_storyboard(text, "s.toml", DRAGON_SOURCE_DIR, assets); }

TEST(Film, ShotsLieEndToEndWithTheirCrossfades) {
    const Film film(parse(R"(
[film]
size = "160x90"
fps = 10
[[shot]]
title = "card"
duration = 2
[[shot]]
from = 100
to = 110
rate = 5
transition = { crossfade = 0.5 }
[[shot]]
from = 50
to = 51
duration = 1
freeze = { seconds = 0.3 }
)"));
    // 2 s of card; 10 s at 5 s per second: 2 s, 21 frames with the last at 110 s; then 1 s
    // (11 frames) and 3 held; the crossfade takes 5 frames off the sum.
    ASSERT_EQ(film.spans().size(), 3u);
    EXPECT_EQ(film.spans()[0].count, 20);
    EXPECT_EQ(film.spans()[1].count, 21);
    EXPECT_EQ(film.spans()[1].first, 15);
    EXPECT_EQ(film.spans()[1].fade, 5);
    EXPECT_EQ(film.spans()[2].first, 36);
    EXPECT_EQ(film.spans()[2].count, 14);
    EXPECT_EQ(film.frame_count(), 50);
    EXPECT_DOUBLE_EQ(film.duration(), 5.0);
    for (int i = 0; i < 21; ++i) EXPECT_NEAR(film.time_at(1, i), 100.0 + 0.5 * i, 1e-12) << i;
    for (int i = 11; i < 14; ++i) EXPECT_EQ(film.time_at(2, i), 51.0);
    EXPECT_EQ(film.scene_at(2, 13, 0).rate, "held");
    EXPECT_EQ(film.scene_at(1, 3, 0).rate, "\u00d75");
}

TEST(Film, CollisionAndBoundaryAreTheRunsOwn) {
    const Film film(parse("[[shot]]\nfrom = \"boundary - 1\"\nto = \"collision\"\nrate = 100\n"));
    const Simulation sim(Scenario{});
    const std::optional<Contact> c = first_contact(sim, 0.0, sim.valid_end());
    ASSERT_TRUE(c);
    const int last = film.spans()[0].count - 1;
    EXPECT_EQ(film.time_at(0, last), c->time);
    EXPECT_EQ(film.time_at(0, 0), boundary_time(sim) - 1.0);
    // The last frame marks the touching pair and says so.
    const Scene s = film.scene_at(0, last);
    ASSERT_TRUE(s.collision);
    EXPECT_EQ(s.collision->bench_a, c->bench_a);
    EXPECT_EQ(s.collision->bench_b, c->bench_b);
    ASSERT_EQ(s.captions.size(), 1u);
    EXPECT_EQ(s.captions[0].text, fmt::format("first contact: bench {} touches bench {}, t = {:.6f} s", c->bench_a,
                                              c->bench_b, c->time));
    // The head reaching the turning space is said from its frame (1 s in, at 100 s per second).
    EXPECT_TRUE(film.scene_at(0, 0).captions.empty());
    const Scene at_boundary = film.scene_at(0, static_cast<int>(std::ceil(0.01 * 30)));
    ASSERT_EQ(at_boundary.captions.size(), 1u);
    EXPECT_NE(at_boundary.captions[0].text.find("turning space"), std::string::npos);
}

// Each failure names the shot and the key, as the user wrote them.
void expect_refused(const std::string& toml, int shot, const std::string& key, const std::string& says) {
    try {
        Film film(parse(toml));
        FAIL() << "accepted: " << toml;
    } catch (const StoryboardError& e) {
        EXPECT_EQ(e.shot, shot) << e.what();
        EXPECT_EQ(e.key, key) << e.what();
        EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
    }
}

TEST(Film, ShotsPastTheValidMotionAreRefused) {
    const Simulation sim(Scenario{});
    const std::string end = fmt::format("{:.6f}", sim.valid_end());
    expect_refused("[[shot]]\nfrom = 0\nto = 10\nrate = 5\n[[shot]]\nname = \"late\"\nfrom = 400\nto = 433\nrate = 5\n",
                   2, "to", "the dragon can follow its path only until t = 432.9179");
    expect_refused("[[shot]]\nfrom = \"end + 1\"\nto = \"end + 2\"\nrate = 5\n", 1, "from", "can follow its path only");
    expect_refused("[[shot]]\nfrom = 10\nto = 5\nrate = 5\n", 1, "to", "is not after from");
    // A turnaround runs for ever: it has no end to name.
    expect_refused("[[shot]]\npath = \"turnaround\"\nto = \"end\"\nrate = 5\n", 1, "to", "follows this path for ever");
    // No contact on a turnaround with the contest's design before an hour is up.
    expect_refused("[[shot]]\npath = \"turnaround\"\nfrom = 0\nto = 10\nrate = 5\ncamera = { contact = 2 }\n", 1,
                   "camera", "no two benches touch");
    // The freeze's slow motion and captions are checked against the run too.
    expect_refused("[[shot]]\nfrom = 0\nto = 10\nrate = 5\ncaptions = [{ text = \"x\", at = 20 }]\n", 1,
                   "captions[1].at", "outside the shot");
    expect_refused("[[shot]]\nsplit = [{ to = 10 }, { to = 500 }]\nfrom = 0\nrate = 5\n", 1, "split[2].to",
                   "can follow its path only");
}

TEST(Film, OverlappingTransitionsAreRefused) {
    const std::string a = "[[shot]]\nfrom = 0\nto = 10\nrate = 10\n";  // 1 s
    // 0.6 s in and 0.6 s out of a 1 s shot overlap.
    expect_refused(a + a + "transition = { crossfade = 0.6 }\n" + a + "transition = { crossfade = 0.6 }\n", 3,
                   "transition", "overlaps the one into shot 2");
    expect_refused(a + "transition = { crossfade = 0.5 }\n", 1, "transition", "no shot before it");
    expect_refused(a + a + "transition = { crossfade = 5 }\n", 2, "transition.crossfade", "longer than this shot");
}

TEST(Film, SlowMotionSlowsNearItsMomentAndKeepsTheDuration) {
    const Film film(parse(R"(
[film]
fps = 20
[[shot]]
from = 100
to = 140
duration = 8
slow = { at = 120, within = 1, rate = 0.5 }
)"));
    const int n = film.spans()[0].count;
    EXPECT_EQ(n, 8 * 20 + 1);
    double last = film.time_at(0, 0);
    EXPECT_EQ(last, 100.0);
    double slowest = 1e9, fastest = 0;
    for (int i = 1; i < n; ++i) {
        const double t = film.time_at(0, i);
        ASSERT_GT(t, last) << i;
        const double rate = (t - last) * 20;
        if (std::abs(t - 120) < 1.5) slowest = std::min(slowest, rate);
        fastest = std::max(fastest, rate);
        last = t;
    }
    EXPECT_EQ(last, 140.0);
    EXPECT_NEAR(slowest, 0.5, 0.01);
    // 38 simulated s outside the 2 s window (and its easing) in under 4 s of film: faster than 9.5.
    EXPECT_GT(fastest, 9.5);
    EXPECT_EQ(film.scene_at(0, n / 2).rate, "\u00d70.5");
    // A duration the slow stretch alone outlasts (4 s at half speed: 8 s of film) is refused.
    EXPECT_THROW(Film(parse("[[shot]]\nfrom = 100\nto = 140\nduration = 8\nslow = { at = 120, within = 2, rate = 0.5 }\n")),
                 StoryboardError);
}

TEST(Film, SplitPanesKeepTheirOwnClocks) {
    const Film film(parse("[film]\nfps = 10\n[[shot]]\nrate = 2\nfrom = 100\nsplit = [{ to = 101 }, { to = 102 }]\n"));
    // The longer pane sets the shot: 2 s at 2 s per second, 11 frames; the shorter holds at its end.
    EXPECT_EQ(film.spans()[0].count, 11);
    EXPECT_DOUBLE_EQ(film.time_at(0, 3, 0), 100.6);
    EXPECT_EQ(film.time_at(0, 8, 0), 101.0);
    EXPECT_DOUBLE_EQ(film.time_at(0, 8, 1), 101.6);
    EXPECT_EQ(film.scene_at(0, 8, 0).rate, "held");
}

TEST(Film, TheContestStoryboardTellsTheWholeProblemInAMinuteOrTwo) {
    const Film film(load_storyboard(assets + "/films/contest.toml", assets));
    EXPECT_GE(film.duration(), 60.0);
    EXPECT_LE(film.duration(), 90.0);
    EXPECT_EQ(film.settings().width, 1280);
    EXPECT_EQ(film.spans().size(), 8u);
}

}  // namespace
