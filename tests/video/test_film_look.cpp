// What a film says besides the dragon: the clock and rate, captions at events, the legend and
// the inset of a close view.
#include <cmath>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "dragon/analyses.hpp"
#include "dragon/video.hpp"

using namespace dragon;

namespace {

// The head's distance from the centre at t, from the frame itself.
double head_radius(const Simulation& sim, double t) { return norm(sim.frame(t).handles[0].pos); }

TEST(FilmLook, EventsAreTheBoundaryTheContactAndTheEndOfTheValidMotion) {
    const Simulation sim(Scenario{});
    const CollisionMark mark{1, 9, {1.2, 1.9}};
    const std::vector<FilmEvent> ev = clip_events(sim, 300.0, 412.473838, mark);
    ASSERT_EQ(ev.size(), 2u);
    // The head crosses r = 4.5 m at the first event's time (checked on the frames around it).
    EXPECT_LT(head_radius(sim, ev[0].time + 1e-6), 4.5);
    EXPECT_GT(head_radius(sim, ev[0].time - 1e-6), 4.5);
    EXPECT_NE(ev[0].caption.find("head reaches the turning space"), std::string::npos) << ev[0].caption;
    EXPECT_EQ(ev[1].time, 412.473838);
    EXPECT_EQ(ev[1].caption, "first contact: bench 1 touches bench 9, t = 412.473838 s");
    // A clip that passes the first contact says so where it happens (the same contact the
    // exact search finds)...
    const std::optional<Contact> hit = first_contact(sim, 0.0, sim.valid_end());
    ASSERT_TRUE(hit);
    const std::vector<FilmEvent> passing = clip_events(sim, 405.0, 420.0, std::nullopt);
    ASSERT_EQ(passing.size(), 1u);
    EXPECT_EQ(passing[0].time, hit->time);
    EXPECT_EQ(passing[0].caption, contact_caption({hit->bench_a, hit->bench_b, hit->point}, hit->time));
    // ... and one that stops where the dragon can no longer follow its path, starting after
    // the first contact, says both.
    const double end = sim.valid_end();
    const std::vector<FilmEvent> at_end = clip_events(sim, end - 1.0, end, std::nullopt);
    ASSERT_EQ(at_end.size(), 2u);
    EXPECT_EQ(at_end[0].time, end - 1.0);
    EXPECT_NE(at_end[0].caption.find("past the first contact (bench 1 touches bench 9"), std::string::npos)
        << at_end[0].caption;
    EXPECT_EQ(at_end[1].time, end);
    EXPECT_NE(at_end[1].caption.find("end of the valid motion"), std::string::npos) << at_end[1].caption;
    EXPECT_NE(at_end[1].caption.find("handle 1"), std::string::npos) << at_end[1].caption;
    // Before the boundary nothing happens.
    EXPECT_TRUE(clip_events(sim, 0.0, 100.0, std::nullopt).empty());
}

TEST(FilmLook, ClockRateAndCaptionsFollowTheFrames) {
    const Simulation sim(Scenario{});
    FilmLook look;
    look.events = {{12.0, "twelve"}, {14.0, "fourteen"}};
    look.caption_seconds = 1.0;
    // 10 .. 15 s at 2 s per second of film, 10 frames a second: frame i shows 10 + 0.2 i s.
    const Animation anim(sim, Clip{10.0, 15.0, 2.0, 1.0}, 10, SceneOptions{}, std::nullopt, look);
    for (int i = 0; i < anim.frame_count(); ++i) {
        const Scene s = anim.scene_at(i);
        const double t = anim.time_at(i);
        EXPECT_EQ(s.clock, fmt::format("t = {:.3f} s", t)) << i;
        EXPECT_EQ(s.rate, i < anim.distinct_frames() ? "\u00d72" : "held") << i;
        // "twelve" from frame 10 (12 s) for 1 s of film (10 frames), "fourteen" from frame 20,
        // which takes its place; none on the held frames after 15 s once a second has passed.
        std::string want;
        if (i >= 10 && i < 20) want = "twelve";
        if (i >= 20 && i < 30) want = "fourteen";
        ASSERT_EQ(s.captions.size(), want.empty() ? 0u : 1u) << "frame " << i;
        if (!want.empty()) {
            EXPECT_EQ(s.captions[0].text, want) << i;
        }
    }
    // Fading out over the last half second of its stay.
    EXPECT_DOUBLE_EQ(anim.scene_at(12).captions[0].opacity, 1.0);
    EXPECT_NEAR(anim.scene_at(18).captions[0].opacity, 0.4, 1e-9);
    // The clock names the time, so the annotation names the scenario.
    EXPECT_EQ(anim.scene_at(0).annotation, "Coiling in: pitch 0.55 m, head 1 m/s");
    EXPECT_TRUE(anim.scene_at(0).legend);
}

TEST(FilmLook, ACaptionOnTheLastMomentStaysToTheEnd) {
    const Simulation sim(Scenario{});
    FilmLook look;
    look.events = {{11.0, "the end"}};
    const Animation anim(sim, Clip{10.0, 11.0, 1.0, 5.0}, 10, SceneOptions{}, std::nullopt, look);
    for (int i = anim.distinct_frames() - 1; i < anim.frame_count(); ++i)
        ASSERT_EQ(anim.scene_at(i).captions.size(), 1u) << i;
    EXPECT_TRUE(anim.scene_at(anim.distinct_frames() - 2).captions.empty());
}

TEST(FilmLook, InsetOnlyForACloseView) {
    const Simulation sim(Scenario{});
    const Clip clip{100.0, 101.0, 1.0};
    EXPECT_FALSE(Animation(sim, clip, 5, SceneOptions{}).scene_at(0).inset);
    SceneOptions follow;
    follow.camera = Camera::follow(6.0);
    const Animation close(sim, clip, 5, follow);
    ASSERT_TRUE(close.scene_at(0).inset);
    // The inset's view is one for the clip: the same at both ends, and it holds the dragon.
    const Scene a = *close.scene_at(0).inset, b = *close.scene_at(close.frame_count() - 1).inset;
    EXPECT_EQ(a.view_centre.x(), b.view_centre.x());
    EXPECT_EQ(a.view_width, b.view_width);
    EXPECT_GT(a.view_width, 16.0);  // the dragon spans about 17.6 m at 100 s
    FilmLook none;
    none.inset = none.legend = none.clock = false;
    const Scene bare = Animation(sim, clip, 5, follow, std::nullopt, none).scene_at(0);
    EXPECT_FALSE(bare.inset);
    EXPECT_FALSE(bare.legend);
    EXPECT_EQ(bare.clock, "");
}

}  // namespace
