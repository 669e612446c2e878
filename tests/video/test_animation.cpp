// Films of a simulation: frame timing, the clip's checks, and a decoded frame against the
// renderer's own picture of that moment.
#include <atomic>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "support/scratch.hpp"

#include "render/cairo_handles.hpp"
#include "dragon/scenario.hpp"
#include "dragon/video.hpp"
#include "video/decode.hpp"

namespace fs = std::filesystem;
using namespace dragon;

namespace {

std::string scratch(const std::string& name) {
    const fs::path dir = dragon_test::scratch_dir();
    const fs::path p = dir / name;
    fs::remove(p);
    return p.string();
}

test::Rgb rendered(const Animation& anim, int index, int width, int height) {
    cairo::Surface s(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height));
    cairo::Context cr(cairo_create(s.get()));
    anim.paint(index, cr.get(), width, height);
    cairo_surface_flush(s.get());
    return test::rgb_from_argb32(cairo_image_surface_get_data(s.get()), width, height,
                                 cairo_image_surface_get_stride(s.get()));
}

TEST(Animation, FramesStepBySpeedupOverFpsAndEndExactlyAtTo) {
    const Simulation sim(Scenario{});
    const Clip clip{10.0, 11.05, 0.5, 0.4};  // 1.05 s at 0.5 s per video second
    const double fps = 10;
    const Animation anim(sim, clip, fps, SceneOptions{});
    const double step = clip.speedup / fps;
    const int moving = static_cast<int>(std::ceil((clip.to - clip.from) / step - 1e-9)) + 1;
    const int hold = static_cast<int>(std::lround(clip.hold * fps));
    ASSERT_EQ(anim.frame_count(), moving + hold);
    for (int i = 0; i + 1 < moving; ++i) EXPECT_DOUBLE_EQ(anim.time_at(i), clip.from + i * step);
    for (int i = moving - 1; i < anim.frame_count(); ++i) EXPECT_EQ(anim.time_at(i), clip.to);
    EXPECT_LT(anim.time_at(moving - 2), clip.to);
}

TEST(Animation, WholeStepsGiveNoExtraFrame) {
    const Simulation sim(Scenario{});
    const Animation anim(sim, Clip{0.0, 10.0, 1.0, 0.0}, 30, SceneOptions{});
    EXPECT_EQ(anim.frame_count(), 301);  // 0, 1/30, ..., 10 s
}

TEST(Animation, RejectsEmptyRangesAndTimesOffThePath) {
    const Simulation sim(Scenario{});
    EXPECT_THROW(Animation(sim, Clip{5.0, 5.0}, 30, SceneOptions{}), InputError);
    EXPECT_THROW(Animation(sim, Clip{5.0, 4.0}, 30, SceneOptions{}), InputError);
    EXPECT_THROW(Animation(sim, Clip{0.0, sim.end_time() + 1.0}, 30, SceneOptions{}), InputError);
    EXPECT_THROW(Animation(sim, Clip{0.0, 1.0, 0.0}, 30, SceneOptions{}), InputError);
    EXPECT_THROW(Animation(sim, Clip{0.0, 1.0}, 0.0, SceneOptions{}), InputError);
    EXPECT_THROW(Animation(sim, Clip{0.0, 1.0, 1.0, -1.0}, 30, SceneOptions{}), InputError);
    EXPECT_THROW(Animation(sim, Clip{0.0, 1.0, 1.0, 3601.0}, 30, SceneOptions{}), InputError);
    EXPECT_THROW(Animation(sim, Clip{0.0, 1.0, 1.0, std::nan("")}, 30, SceneOptions{}), InputError);
}

// A held last moment is drawn once: the encoder gets that picture again for every held frame,
// and the film still lasts its whole length and ends on it.
TEST(Animation, HeldLastMomentIsDrawnOnce) {
    const Simulation sim(Scenario{});
    const Clip clip{100.0, 101.0, 1.0, 3.0};
    const double fps = 10;
    const Animation anim(sim, clip, fps, SceneOptions{});
    const int moving = 11;  // 100, 100.1, ..., 101 s
    const int held = 30;    // 3 s at 10 fps
    ASSERT_EQ(anim.distinct_frames(), moving);
    ASSERT_EQ(anim.frame_count(), moving + held);

    VideoOptions opt;  // H.264 at the default quality, as in DecodedH264FrameMatchesTheRenderersPicture
    opt.width = 640;
    opt.height = 360;
    opt.fps = fps;
    std::atomic<int> painted{0};
    const std::string path = scratch("held.mp4");
    const EncodeStats stats = encode_frames(
        path, opt, anim.frame_count(),
        [&](int index, cairo_t* cr) {
            ++painted;
            anim.paint(index, cr, opt.width, opt.height);
        },
        {}, anim.distinct_frames());
    EXPECT_EQ(painted.load(), moving);
    EXPECT_EQ(stats.frames, moving + held);

    const test::DecodedVideo v = test::decode_video(path, moving + held - 1);
    EXPECT_EQ(v.frames, moving + held);
    EXPECT_NEAR(v.duration, (moving + held) / fps, 0.5 / fps);
    EXPECT_GT(test::psnr(v.kept, rendered(anim, moving - 1, opt.width, opt.height)), 30.0);
}

// write_video holds the last moment the same way (for every format: GIF's palette too).
TEST(Animation, WriteVideoHoldsTheLastMoment) {
    const Simulation sim(Scenario{});
    const Animation anim(sim, Clip{10.0, 11.0, 1.0, 2.0}, 5, SceneOptions{});
    VideoOptions opt;
    opt.width = 96;
    opt.height = 64;
    for (const char* name : {"held.mp4", "held.gif"}) {
        const std::string path = scratch(name);
        write_video(anim, path, opt);
        const test::DecodedVideo v = test::decode_video(path, anim.frame_count() - 1);
        EXPECT_EQ(v.frames, anim.frame_count()) << name;
        EXPECT_GT(test::psnr(v.kept, rendered(anim, anim.distinct_frames() - 1, opt.width, opt.height)), 25.0) << name;
    }
}

TEST(Animation, CollisionIsMarkedOnlyAtTheEnd) {
    const Simulation sim(Scenario{});
    const CollisionMark mark{1, 9, {1.0, 2.0}};
    const Animation anim(sim, Clip{0.0, 2.0, 1.0, 0.5}, 4, SceneOptions{}, mark);
    for (int i = 0; i < anim.frame_count(); ++i) {
        const Scene s = anim.scene_at(i);
        EXPECT_EQ(s.collision.has_value(), anim.time_at(i) == 2.0) << "frame " << i;
    }
}

TEST(Animation, ViewStaysFixedWhileTheDragonCoils) {
    const Simulation sim(Scenario{});
    const Animation anim(sim, Clip{0.0, 200.0, 50.0}, 1, SceneOptions{});
    const Scene first = anim.scene_at(0), last = anim.scene_at(anim.frame_count() - 1);
    EXPECT_EQ(first.view_centre.x(), last.view_centre.x());
    EXPECT_EQ(first.view_width, last.view_width);
}

// A still camera shows one stretch of path for the whole clip (drawn once, then copied): it
// covers every frame's own guide, and each painted frame is draw()'s picture of its scene.
TEST(Animation, AStillCameraKeepsOnePathForTheClipAndPaintsEachFrameAsDrawDoes) {
    const Simulation sim(Scenario{});
    const Animation anim(sim, Clip{0.0, 400.0, 80.0}, 1, SceneOptions{});
    const Scene first = anim.scene_at(0);
    ASSERT_FALSE(first.guides.empty());
    const double from = first.guides.front().s0, to = first.guides.back().s1;
    for (int i = 0; i < anim.frame_count(); ++i) {
        const Scene s = anim.scene_at(i);
        ASSERT_EQ(s.guides.size(), first.guides.size());
        for (std::size_t g = 0; g < s.guides.size(); ++g)
            EXPECT_TRUE(s.guides[g].s0 == first.guides[g].s0 && s.guides[g].s1 == first.guides[g].s1) << "frame " << i;
        const auto [own_from, own_to] = guide_arcs_of(sim, sim.frame(anim.time_at(i)));
        EXPECT_LE(from, own_from) << "frame " << i;
        EXPECT_GE(to, own_to) << "frame " << i;
        // Painted (the backdrop copied after the first frame) and drawn afresh.
        cairo::Surface drawn(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 320, 240));
        {
            cairo::Context cr(cairo_create(drawn.get()));
            draw(cr.get(), s, 320, 240);
        }
        cairo_surface_flush(drawn.get());
        const test::Rgb want = test::rgb_from_argb32(cairo_image_surface_get_data(drawn.get()), 320, 240,
                                                     cairo_image_surface_get_stride(drawn.get()));
        EXPECT_EQ(rendered(anim, i, 320, 240).pixels, want.pixels) << "frame " << i;
    }
    // A followed head keeps each frame's own guide.
    SceneOptions follow;
    follow.camera = Camera::follow(12.0);
    const Animation followed(sim, Clip{0.0, 400.0, 80.0}, 1, follow);
    EXPECT_NE(followed.scene_at(0).guides.front().s0, followed.scene_at(5).guides.front().s0);
}

TEST(Animation, SpeedColoursKeepOneRangeForTheClip) {
    Scenario s;
    s.path.kind = PathKind::turnaround;
    const Simulation sim(s);
    SceneOptions opt;
    opt.colour_by_speed = true;
    const Animation anim(sim, Clip{-20.0, 20.0, 10.0}, 2, opt);
    const Scene first = anim.scene_at(0), last = anim.scene_at(anim.frame_count() - 1);
    EXPECT_EQ(first.speed_min, last.speed_min);
    EXPECT_EQ(first.speed_max, last.speed_max);
    EXPECT_LT(first.speed_min, first.speed_max);
}

TEST(Animation, DecodedH264FrameMatchesTheRenderersPicture) {
    Scenario s;
    const Simulation sim(s);
    const Animation anim(sim, Clip{100.0, 104.0, 2.0}, 10, SceneOptions{});
    VideoOptions opt;  // the defaults but the size: H.264, faster, tune animation, crf 23 and the dragon's x264 settings
    opt.width = 640;
    opt.height = 360;
    const std::string path = scratch("coil.mp4");
    const EncodeStats stats = write_video(anim, path, opt);
    EXPECT_EQ(stats.frames, anim.frame_count());

    const int keep = anim.frame_count() / 2;
    const test::DecodedVideo v = test::decode_video(path, keep);
    EXPECT_EQ(v.codec, "h264");
    EXPECT_EQ(v.frames, anim.frame_count());
    EXPECT_EQ(v.width, opt.width);
    EXPECT_EQ(v.height, opt.height);
    EXPECT_NEAR(v.duration, anim.frame_count() / anim.fps(), 0.5 / anim.fps());
    const double db = test::psnr(v.kept, rendered(anim, keep, opt.width, opt.height));
    RecordProperty("psnr_db", std::to_string(db));
    std::printf("PSNR of frame %d (t = %.3f s): %.2f dB\n", keep, anim.time_at(keep), db);
    EXPECT_GT(db, 30.0);
}

TEST(Animation, GifOfTheTurnaroundRoundTrips) {
    Scenario s;
    s.path.kind = PathKind::turnaround;
    const Simulation sim(s);
    const Animation anim(sim, Clip{-4.0, 4.0, 4.0}, 5, SceneOptions{});
    VideoOptions opt;
    opt.width = 200;
    opt.height = 150;
    const std::string path = scratch("turn.gif");
    write_video(anim, path, opt);
    const int keep = 3;
    const test::DecodedVideo v = test::decode_video(path, keep);
    EXPECT_EQ(v.codec, "gif");
    EXPECT_EQ(v.frames, anim.frame_count());
    const double db = test::psnr(v.kept, rendered(anim, keep, opt.width, opt.height));
    std::printf("GIF PSNR of frame %d: %.2f dB\n", keep, db);
    EXPECT_GT(db, 25.0);
}

}  // namespace
