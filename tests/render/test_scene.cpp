#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>

#include "render/cairo_handles.hpp"
#include "dragon/render.hpp"
#include "render/guide.hpp"
#include "render/paint.hpp"

namespace dragon {
namespace {

TEST(Scene, OneBenchPerRectangleWithHeadBodyAndTailApart) {
    const Simulation sim(Scenario{});
    const Frame f = sim.frame(100.0);
    const Scene s = make_scene(sim, f, {});
    ASSERT_EQ(s.benches.size(), f.benches.size());
    ASSERT_EQ(s.handles.size(), f.handles.size());
    EXPECT_EQ(s.benches.front().style, Scene::Style::head);
    EXPECT_EQ(s.benches.back().style, Scene::Style::tail);
    for (std::size_t k = 1; k + 1 < s.benches.size(); ++k) EXPECT_EQ(s.benches[k].style, Scene::Style::body);
    EXPECT_FALSE(s.guides.empty());
    ASSERT_TRUE(s.turning_radius.has_value());
}

TEST(Scene, FitCameraHoldsEveryCorner) {
    const Simulation sim(Scenario{});
    const Frame f = sim.frame(200.0);
    const Scene s = make_scene(sim, f, {});
    for (const Rect& r : f.benches)
        for (Vec2 p : corners(r).p) {
            EXPECT_LE(std::abs(p.x() - s.view_centre.x()), 0.5 * s.view_width);
            EXPECT_LE(std::abs(p.y() - s.view_centre.y()), 0.5 * s.view_height);
        }
}

TEST(Scene, CollisionMarkOverridesTheStyleOfBothBenches) {
    const Simulation sim(Scenario{});
    SceneOptions o;
    o.collision = CollisionMark{3, 20, {1, 2}};
    o.camera = Camera::follow(5.0);
    const Frame f = sim.frame(50.0);
    const Scene s = make_scene(sim, f, o);
    EXPECT_EQ(s.benches[2].style, Scene::Style::collision);
    EXPECT_EQ(s.benches[19].style, Scene::Style::collision);
    EXPECT_DOUBLE_EQ(s.view_centre.x(), f.handles[0].pos.x());
    EXPECT_DOUBLE_EQ(s.view_width, 5.0);
}

TEST(Scene, GuideBeziersFollowThePathWithinAMillimetre) {
    const Simulation sim(Scenario{});
    const Path& path = sim.path();
    const double s0 = sim.head_arc(0) - 300, s1 = path.s_max();
    const auto runs = render::path_beziers(path, s0, s1, 1.0);
    ASSERT_EQ(runs.size(), 1u);
    // Each segment's midpoint (t = 1/2) against the path: the point nearest it on the path is
    // found by sampling the segment's arc range finely.
    const auto& b = runs[0].beziers;
    double worst = 0;
    for (std::size_t i = 0; i + 3 < b.size(); i += 30) {
        const Vec2 mid = 0.125 * (b[i] + 3.0 * b[i + 1] + 3.0 * b[i + 2] + b[i + 3]);
        // Distance from the spiral r = b theta: |r - b theta| at the nearest branch is a fine
        // proxy (the spiral's rings are 0.55 m apart).
        const double bb = 0.55 / (2 * std::acos(-1.0));
        const double r = norm(mid);
        double th = std::atan2(mid.y(), mid.x());
        if (th < 0) th += 2 * std::acos(-1.0);
        double best = 1e9;
        for (int k = 0; k < 40; ++k) best = std::min(best, std::abs(r - bb * (th + 2 * std::acos(-1.0) * k)));
        worst = std::max(worst, best);
    }
    EXPECT_LT(worst, 1e-3);
}

TEST(Scene, DrawPaintsEveryPixelOpaque) {
    const Simulation sim(Scenario{});
    const Scene s = make_scene(sim, sim.frame(10.0), {});
    cairo::Surface surface(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 64, 48));
    cairo::Context cr = cairo::make_context(surface.get());
    draw(cr.get(), s, 64, 48);
    cairo_surface_flush(surface.get());
    const unsigned char* d = cairo_image_surface_get_data(surface.get());
    const int stride = cairo_image_surface_get_stride(surface.get());
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 64; ++x)
            ASSERT_EQ(reinterpret_cast<const std::uint32_t*>(d + y * stride)[x] >> 24, 0xffu) << x << "," << y;
}

TEST(Scene, PngIsWrittenWholeAndBadPathsAreInputErrors) {
    const Simulation sim(Scenario{});
    const Scene s = make_scene(sim, sim.frame(0.0), {});
    const std::filesystem::path dir = std::filesystem::path(DRAGON_TEST_TMP) / "png";
    std::filesystem::create_directories(dir);
    const auto file = dir / "t0.png";
    render_png(s, 200, 150, file.string());
    cairo::Surface back(cairo_image_surface_create_from_png(file.c_str()));
    ASSERT_EQ(cairo_surface_status(back.get()), CAIRO_STATUS_SUCCESS);
    EXPECT_EQ(cairo_image_surface_get_width(back.get()), 200);
    EXPECT_EQ(cairo_image_surface_get_height(back.get()), 150);
    EXPECT_THROW(render_png(s, 200, 150, "/no/such/dir/x.png"), InputError);
    EXPECT_THROW(render_png(s, 0, 150, (dir / "zero.png").string()), InputError);
    EXPECT_FALSE(std::filesystem::exists(dir / "zero.png"));
}

TEST(Paint, NiceTicksAreRoundAndCoverTheRange) {
    const auto t = render::nice_ticks(0.0, 300.0, 6);
    EXPECT_DOUBLE_EQ(t.step, 50.0);
    EXPECT_DOUBLE_EQ(t.values.front(), 0.0);
    EXPECT_DOUBLE_EQ(t.values.back(), 300.0);
    // A narrow range (the speeds of Q1): still a handful of ticks, all inside, round steps.
    const auto small = render::nice_ticks(0.99931, 1.0, 5);
    EXPECT_GE(small.values.size(), 3u);
    EXPECT_LE(small.values.size(), 11u);
    for (double v : small.values) EXPECT_TRUE(v >= 0.99931 - 1e-12 && v <= 1.0 + 1e-12) << v;
    const double mantissa = small.step / std::pow(10.0, std::floor(std::log10(small.step)));
    EXPECT_TRUE(std::abs(mantissa - 1) < 1e-9 || std::abs(mantissa - 2) < 1e-9 || std::abs(mantissa - 5) < 1e-9);
    EXPECT_EQ(small.decimals, 4);
    EXPECT_EQ(render::format_tick(-0.0, 1), "0.0");
    EXPECT_EQ(render::format_tick(-2.5, 1), "\u22122.5");
    EXPECT_DOUBLE_EQ(render::nice_floor(7.3), 5.0);
    EXPECT_DOUBLE_EQ(render::nice_floor(0.31), 0.2);
}

}  // namespace
}  // namespace dragon
