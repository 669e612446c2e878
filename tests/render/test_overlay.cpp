// The screen furniture of films: captions, the legend, the clock and the inset. Golden images at
// two sizes (DejaVu Sans, the pinned font, drawn without hinting so glyph outlines alone decide
// the pixels), and measurements of the text's size on a small picture.
#include <algorithm>
#include <cstdint>

#include <gtest/gtest.h>

#include "render/cairo_handles.hpp"
#include "dragon/render.hpp"
#include "golden.hpp"

namespace dragon {
namespace {

Theme light() { return load_theme("light", std::string(DRAGON_SOURCE_DIR) + "/assets"); }

cairo::Surface drawn(const Scene& scene, int w, int h) {
    cairo::Surface surface(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, w, h));
    cairo::Context cr = cairo::make_context(surface.get());
    test::outline_fonts(cr.get());
    draw(cr.get(), scene, w, h);
    EXPECT_EQ(cairo_status(cr.get()), CAIRO_STATUS_SUCCESS);
    cairo_surface_flush(surface.get());
    return surface;
}

// The head at the first contact of the contest's run, followed in a 6 m view: the legend with
// its touching entry, the clock and rate, a caption and the inset of the whole dragon.
Scene furnished() {
    const Simulation sim(Scenario{});
    const double t = 412.473838;  // the contest's first contact, to the microsecond
    SceneOptions o;
    o.theme = light();
    o.camera = Camera::follow(6.0);
    o.collision = CollisionMark{1, 9, sim.frame(t).handles[0].pos};
    o.show_legend = true;
    o.show_inset = true;
    o.annotation = "Coiling in: pitch 0.55 m, head 1 m/s";
    Scene s = make_scene(sim, sim.frame(t), o);
    s.clock = "t = 412.474 s";
    s.rate = "\u00d720";
    s.captions.push_back({"first contact: bench 1 touches bench 9, t = 412.473838 s", 1.0});
    return s;
}

TEST(Overlay, CaptionLegendClockAndInsetSmall) {
    const cairo::Surface s = drawn(furnished(), 320, 240);
    const auto r = test::compare_golden(s.get(), "overlay_contact_follow6m_caption_legend_inset_320x240.png");
    EXPECT_TRUE(r.ok) << r.message;
}

TEST(Overlay, CaptionLegendClockAndInsetLarge) {
    const cairo::Surface s = drawn(furnished(), 960, 540);
    const auto r = test::compare_golden(s.get(), "overlay_contact_follow6m_caption_legend_inset_960x540.png");
    EXPECT_TRUE(r.ok) << r.message;
}

// Rows of the picture with ink (pixels darker than mid grey) within the box x0..x1, y0..y1.
std::pair<int, int> inked_rows(cairo_surface_t* s, int x0, int x1, int y0, int y1) {
    const auto* data = cairo_image_surface_get_data(s);
    const int stride = cairo_image_surface_get_stride(s);
    int first = -1, last = -1;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            const std::uint32_t px = reinterpret_cast<const std::uint32_t*>(data + y * stride)[x];
            if (((px >> 8) & 0xff) < 110) {
                if (first < 0) first = y;
                last = y;
            }
        }
    return {first, last};
}

// A 400 x 300 film (the README's GIF) once set its clock 5 px tall. The clock's digits are now
// as tall as an 11 px label's capitals at least (DejaVu's digits: 0.73 em).
TEST(Overlay, ClockReadsOnASmallFilm) {
    Scene s;
    s.theme = light();
    s.show_scale_bar = false;
    s.annotation = "";
    s.clock = "t = 412.474 s";
    const cairo::Surface small = drawn(s, 400, 300);
    const auto [top, bottom] = inked_rows(small.get(), 200, 400, 0, 60);
    ASSERT_GE(top, 0) << "no clock drawn";
    EXPECT_GE(bottom - top + 1, static_cast<int>(0.73 * kMinTextPx)) << "rows " << top << ".." << bottom;
    // And it grows with the picture's height: at 1600 x 1200 the clock's 17 px (at 800) are
    // 25.5 px, its digits 18.6 px tall.
    const cairo::Surface big = drawn(s, 1600, 1200);
    const auto [btop, bbottom] = inked_rows(big.get(), 800, 1600, 0, 240);
    EXPECT_NEAR(bbottom - btop + 1, 17 * 1.5 * 0.73, 2.5);
}

// A caption names the contact in words; a legend's rows and the inset add ink where the bare
// picture has none (the three corners they take).
TEST(Overlay, FurnitureTakesItsCorners) {
    Scene bare = furnished();
    bare.legend = false;
    bare.captions.clear();
    bare.inset.reset();
    const cairo::Surface with = drawn(furnished(), 960, 540), without = drawn(bare, 960, 540);
    auto differs = [&](int x0, int x1, int y0, int y1) {
        const auto* a = cairo_image_surface_get_data(with.get());
        const auto* b = cairo_image_surface_get_data(without.get());
        const int stride = cairo_image_surface_get_stride(with.get());
        int n = 0;
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x)
                n += reinterpret_cast<const std::uint32_t*>(a + y * stride)[x] !=
                     reinterpret_cast<const std::uint32_t*>(b + y * stride)[x];
        return n;
    };
    EXPECT_GT(differs(0, 200, 40, 200), 500) << "legend, top left under the annotation";
    EXPECT_GT(differs(300, 660, 480, 540), 500) << "caption, bottom centre";
    EXPECT_GT(differs(780, 960, 360, 540), 5000) << "inset, bottom right";
    EXPECT_EQ(differs(300, 660, 200, 340), 0) << "the middle of the picture is the dragon's";
}

}  // namespace
}  // namespace dragon
