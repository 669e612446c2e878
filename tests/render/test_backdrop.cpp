// A backdrop copied from the cache is the backdrop draw() draws: frame after frame of a still
// camera, the picture drawn reusing it is draw()'s picture byte for byte, and a target the copy
// cannot stand for (another view, a transform, a clip) is drawn afresh.
#include <cstring>
#include <string>
#include <vector>

#include <cairo.h>
#include <gtest/gtest.h>

#include "dragon/render.hpp"
#include "render/backdrop.hpp"
#include "render/cairo_handles.hpp"

namespace dragon {
namespace {

constexpr int kW = 640, kH = 360;

std::vector<unsigned char> pixels_of(cairo_surface_t* s) {
    cairo_surface_flush(s);
    const unsigned char* d = cairo_image_surface_get_data(s);
    return {d, d + static_cast<std::size_t>(cairo_image_surface_get_stride(s)) * cairo_image_surface_get_height(s)};
}

// The scene drawn by draw() and by draw_reusing_backdrop() with `cache`, each onto a fresh
// surface that starts as garbage (a copy must cover everything the backdrop covers).
struct TwoPictures {
    std::vector<unsigned char> drawn, reused;
};
TwoPictures both_ways(const Scene& scene, render::BackdropCache& cache, cairo_format_t format = CAIRO_FORMAT_ARGB32) {
    TwoPictures out;
    for (int way = 0; way < 2; ++way) {
        cairo::Surface s(cairo_image_surface_create(format, kW, kH));
        cairo_surface_flush(s.get());
        std::memset(cairo_image_surface_get_data(s.get()), 0x5a,
                    static_cast<std::size_t>(cairo_image_surface_get_stride(s.get())) * kH);
        cairo_surface_mark_dirty(s.get());
        cairo::Context cr = cairo::make_context(s.get());
        if (way == 0) draw(cr.get(), scene, kW, kH);
        else render::draw_reusing_backdrop(cr.get(), scene, kW, kH, cache);
        (way == 0 ? out.drawn : out.reused) = pixels_of(s.get());
    }
    return out;
}

struct Backdrop : ::testing::Test {
    Simulation sim{Scenario{}};
    SceneOptions opt;
    void SetUp() override {
        opt.theme = load_theme("light", std::string(DRAGON_SOURCE_DIR) + "/assets");
        opt.camera = Camera::at({0.0, 0.0}, 20.0);
        opt.show_legend = true;
        opt.colour_by_speed = true;  // the colour bar's strip is kept clear of the world
        opt.guide_arcs = guide_arcs_of(sim, sim.frame(100.0));
    }
};

TEST_F(Backdrop, EveryFrameOfAStillCameraIsTheDrawnPictureByteForByte) {
    for (cairo_format_t format : {CAIRO_FORMAT_ARGB32, CAIRO_FORMAT_RGB24}) {
        render::BackdropCache cache;
        for (int i = 0; i < 6; ++i) {
            const Scene scene = make_scene(sim, sim.frame(100.0 + 7.0 * i), opt);
            const TwoPictures p = both_ways(scene, cache, format);
            ASSERT_EQ(p.drawn, p.reused) << "frame " << i << ", format " << format;
        }
        // The first two frames draw the backdrop (the second keeps it), the four after copy it.
        EXPECT_EQ(cache.hits(), 4) << "format " << format;
    }
}

TEST_F(Backdrop, AFrameWithAnotherViewOrPathIsDrawnAfresh) {
    render::BackdropCache cache;
    const Scene first = make_scene(sim, sim.frame(100.0), opt);
    both_ways(first, cache);
    SceneOptions moved = opt;
    moved.camera = Camera::at({1.0, 0.0}, 20.0);
    SceneOptions longer = opt;
    longer.guide_arcs->first -= 5.0;
    SceneOptions dark = opt;
    dark.theme = load_theme("dark", std::string(DRAGON_SOURCE_DIR) + "/assets");
    for (const SceneOptions* o : {&moved, &longer, &dark}) {
        const TwoPictures p = both_ways(make_scene(sim, sim.frame(100.0), *o), cache);
        EXPECT_EQ(p.drawn, p.reused);
    }
    EXPECT_EQ(cache.hits(), 0);
    // The default guide (the frame's own, less what lies under the benches) changes as the
    // dragon moves: each frame is drawn in full.
    SceneOptions own = opt;
    own.guide_arcs.reset();
    render::BackdropCache fresh;
    for (double t : {100.0, 101.0}) {
        const TwoPictures p = both_ways(make_scene(sim, sim.frame(t), own), fresh);
        EXPECT_EQ(p.drawn, p.reused);
    }
    EXPECT_EQ(fresh.hits(), 0);
}

TEST_F(Backdrop, ATransformedOrClippedTargetIsDrawnAsDrawDrawsIt) {
    render::BackdropCache cache;
    const Scene scene = make_scene(sim, sim.frame(100.0), opt);
    both_ways(scene, cache);
    both_ways(scene, cache);  // drawn twice: the backdrop is now kept
    for (int kind = 0; kind < 2; ++kind) {
        std::vector<unsigned char> pictures[2];
        for (int way = 0; way < 2; ++way) {
            cairo::Surface s(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, kW, kH));
            cairo::Context cr = cairo::make_context(s.get());
            if (kind == 0) cairo_translate(cr.get(), 3, 0);
            else {
                cairo_rectangle(cr.get(), 0, 0, kW / 2, kH);
                cairo_clip(cr.get());
            }
            if (way == 0) draw(cr.get(), scene, kW, kH);
            else render::draw_reusing_backdrop(cr.get(), scene, kW, kH, cache);
            pictures[way] = pixels_of(s.get());
        }
        EXPECT_EQ(pictures[0], pictures[1]) << (kind == 0 ? "translated" : "clipped");
    }
    EXPECT_EQ(cache.hits(), 0);
    both_ways(scene, cache);  // the whole target again: the kept backdrop is there
    EXPECT_EQ(cache.hits(), 1);
}

// A camera that moves draws a new backdrop every frame: none is kept (no frame pays for a copy
// no later frame uses), so even the view just drawn is drawn again when it comes back once.
TEST_F(Backdrop, AMovingCameraKeepsNothing) {
    render::BackdropCache cache;
    SceneOptions o = opt;
    for (int i = 0; i < 4; ++i) {
        o.camera = Camera::at({0.25 * i, 0.0}, 20.0);
        const TwoPictures p = both_ways(make_scene(sim, sim.frame(100.0 + i), o), cache);
        EXPECT_EQ(p.drawn, p.reused) << "frame " << i;
    }
    EXPECT_EQ(cache.hits(), 0);
    both_ways(make_scene(sim, sim.frame(104.0), o), cache);  // the last view again: now kept
    EXPECT_EQ(cache.hits(), 0);
    both_ways(make_scene(sim, sim.frame(105.0), o), cache);  // and copied from here on
    EXPECT_EQ(cache.hits(), 1);
}

}  // namespace
}  // namespace dragon
