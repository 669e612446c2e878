// A storyboard's film decoded back: its length, its frames, each shot where it belongs (a frame
// of each against `dragon render`'s picture of that moment), and a captioned frame against a
// golden image.
#include <cstdlib>
#include <filesystem>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "render/cairo_handles.hpp"
#include "dragon/film.hpp"
#include "dragon/look.hpp"
#include "dragon/picture_bytes.hpp"
#include "dragon/still.hpp"
#include "render/golden.hpp"
#include "support/scratch.hpp"
#include "video/decode.hpp"

using namespace dragon;
namespace fs = std::filesystem;

namespace {

const std::string assets = std::string(DRAGON_SOURCE_DIR) + "/assets";

// A title card, a coil-in stretch, the turnaround and a split screen; no text and no inset on
// the scenes, so that `dragon render --no-text` draws the same pictures.
const char* story = R"(
[film]
size = "192x108"
fps = 10
[[shot]]
title = "One"
duration = 1
[[shot]]
from = 100
to = 102
rate = 1
camera = { centre = [0, 0], extent = 20 }
text = false
inset = false
[[shot]]
path = "turnaround"
from = -2
to = 2
rate = 2
camera = { centre = [0, 0], extent = 20 }
text = false
inset = false
[[shot]]
from = 50
to = 51
rate = 1
camera = { centre = [0, 0], extent = 20 }
text = false
inset = false
split = [{ pitch = 0.5 }, { pitch = 0.6 }]
)";

// One moment drawn as `dragon render --zoom 20 --centre 0 0 --no-text` draws it (the library's
// picture request), as a picture: the film layer is checked against the render layer alone.
test::Rgb rendered(const Scenario& scenario, double t, int w, int h) {
    LookRequest look;
    look.zoom = 20.0;
    look.centre = Vec2(0.0, 0.0);
    look.text = false;
    const Simulation sim(scenario);
    const Still still = still_at(sim, t, picture_scene_options(look, assets));
    const std::vector<std::uint8_t> rgba = render_rgba(still.scene, w, h);
    test::Rgb out{w, h, {}};
    for (std::size_t i = 0; i < rgba.size(); i += 4) out.pixels.insert(out.pixels.end(), rgba.begin() + i, rgba.begin() + i + 3);
    return out;
}

Scenario on(PathKind path, double pitch = Scenario{}.path.pitch) {
    Scenario s;
    s.path.kind = path;
    s.path.pitch = pitch;
    return s;
}

// The left or right part of a picture, `width` pixels wide.
test::Rgb part(const test::Rgb& p, int x0, int width) {
    test::Rgb out{width, p.height, {}};
    for (int y = 0; y < p.height; ++y)
        for (int x = x0; x < x0 + width; ++x)
            for (int c = 0; c < 3; ++c) out.pixels.push_back(p.pixels[(static_cast<size_t>(y) * p.width + x) * 3 + c]);
    return out;
}

TEST(FilmDecode, LengthFramesAndEveryShotInItsPlace) {
    const Storyboard board = parse_storyboard(story, "story.toml", DRAGON_SOURCE_DIR, assets);
    const Film film(board);
    // 1 s of card, (102 - 100) / 1 s, (2 - -2) / 2 s and (51 - 50) / 1 s of scenes at 10 frames a
    // second, each scene with its last moment as a frame of its own.
    const int frames = 10 + 21 + 21 + 11;
    ASSERT_EQ(film.frame_count(), frames);
    const std::string path = (dragon_test::scratch_dir() / "film.mp4").string();
    VideoOptions opt;
    opt.crf = 10;  // near-lossless: the comparison is of the pictures, not of the codec
    write_film(film, path, opt);

    // The card: mostly background, a title in the middle.
    const test::DecodedVideo card = test::decode_video(path, 5);
    EXPECT_EQ(card.frames, frames);
    EXPECT_NEAR(card.duration, frames / 10.0, 0.05);
    EXPECT_EQ(card.width, 192);
    const test::Rgb scene_a = rendered(on(PathKind::spiral), 100.5, 192, 108);
    EXPECT_LT(test::psnr(card.kept, scene_a), 20.0) << "frame 5 is the title card, not the dragon";

    // Each shot's frame against `dragon render` of its moment, and of a moment a second off: the
    // film shows the one. (1-px lines in 4:2:0 chroma cap the PSNR of a 192 x 108 picture near
    // 27 dB even at crf 10, measured on render's own PNG encoded alone; a second off is ~22 dB.)
    const auto expect_shows = [](const test::Rgb& frame, const test::Rgb& right, const test::Rgb& wrong) {
        const double r = test::psnr(frame, right), w = test::psnr(frame, wrong);
        EXPECT_GT(r, 25.0);
        EXPECT_GT(r, w + 3.0) << "right " << r << " dB, a second off " << w << " dB";
    };
    // Shot 2, frame 5: t = 100.5 s.
    expect_shows(test::decode_video(path, 15).kept, scene_a, rendered(on(PathKind::spiral), 101.5, 192, 108));
    // Shot 3, frame 10: t = -2 + 10 * 0.2 = 0 s on the turnaround.
    expect_shows(test::decode_video(path, 41).kept, rendered(on(PathKind::turnaround), 0.0, 192, 108),
                 rendered(on(PathKind::turnaround), 1.0, 192, 108));
    // Shot 4, frame 5: t = 50.5 s at pitch 0.5 m on the left, 0.6 m on the right, each half as wide
    // less the gap.
    const test::Rgb split = test::decode_video(path, 57).kept;
    const int pane = (192 - 6) / 2;
    expect_shows(part(split, 0, pane), rendered(on(PathKind::spiral, 0.5), 50.5, pane, 108),
                 rendered(on(PathKind::spiral, 0.5), 51.5, pane, 108));
    expect_shows(part(split, 192 - pane, pane), rendered(on(PathKind::spiral, 0.6), 50.5, pane, 108),
                 rendered(on(PathKind::spiral, 0.6), 51.5, pane, 108));
    // The two halves differ: not one scene drawn twice.
    EXPECT_LT(test::psnr(part(split, 0, pane), part(split, 192 - pane, pane)), 25.0);
}

// The first contact's freeze, closing in: the caption names the pair and the time, the legend
// and the clock are there (a golden frame, fonts drawn from their outlines alone).
TEST(FilmDecode, CaptionedFrameMatchesItsGoldenImage) {
    const Storyboard board = parse_storyboard(R"(
[film]
size = "480x270"
fps = 10
[[shot]]
from = "collision - 1"
to = "collision"
rate = 1
freeze = { seconds = 1, zoom = 3 }
)", "story.toml", DRAGON_SOURCE_DIR, assets);
    const Film film(board);
    cairo::Surface s(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 480, 270));
    {
        cairo::Context cr = cairo::make_context(s.get());
        test::outline_fonts(cr.get());
        film.paint(film.frame_count() - 1, cr.get());
    }
    const Scene last = film.scene_at(0, film.spans()[0].count - 1);
    ASSERT_EQ(last.captions.size(), 1u);
    EXPECT_EQ(last.captions[0].text, "first contact: bench 1 touches bench 9, t = 412.473838 s");
    const auto r = test::compare_golden(s.get(), "film_contact_freeze_zoom3m_480x270.png");
    EXPECT_TRUE(r.ok) << r.message;
}

}  // namespace
