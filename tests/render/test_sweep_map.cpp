// Maps of a sweep: contour lines by marching squares (on a plane exactly where it has the
// level; around a bowl one closed ring; none through a square without a value), and a golden
// image of a small heat map with its contour lines, colour bar, cells cut short, refused and
// without a value, and the contest's dragon marked. Text is drawn in the pinned DejaVu Sans.
#include <gtest/gtest.h>

#include <cmath>

#include "render/cairo_handles.hpp"
#include "dragon/sweep_map.hpp"
#include "golden.hpp"
#include "render/contours.hpp"

namespace dragon {
namespace {

std::vector<double> steps(double lo, double hi, int n) {
    std::vector<double> v;
    for (int k = 0; k < n; ++k) v.push_back(lo + (hi - lo) * k / (n - 1));
    return v;
}

TEST(Contours, OnAPlaneTheyLieExactlyWhereItHasTheLevel) {
    const std::vector<double> xs = steps(0, 1, 6), ys = steps(0, 2, 5);
    std::vector<double> z;
    for (double x : xs)
        for (double y : ys) z.push_back(x + 2 * y);
    for (double level : {0.3, 1.7, 2.5, 4.2}) {
        const auto lines = render::contour_lines(xs, ys, z, level);
        ASSERT_EQ(lines.size(), 1u) << level;  // one open line across the grid
        EXPECT_GE(lines[0].size(), 2u);
        for (const Vec2& p : lines[0]) EXPECT_NEAR(p.x() + 2 * p.y(), level, 1e-12) << level;
    }
    EXPECT_TRUE(render::contour_lines(xs, ys, z, -1.0).empty());
    EXPECT_TRUE(render::contour_lines(xs, ys, z, 9.0).empty());
}

TEST(Contours, AroundABowlOneClosedRingAndNoneThroughMissingValues) {
    const std::vector<double> xs = steps(-1, 1, 41), ys = steps(-1, 1, 41);
    std::vector<double> z;
    for (double x : xs)
        for (double y : ys) z.push_back(x * x + y * y);
    auto lines = render::contour_lines(xs, ys, z, 0.5);
    ASSERT_EQ(lines.size(), 1u);
    const std::vector<Vec2>& ring = lines[0];
    EXPECT_EQ(ring.front().x(), ring.back().x());
    EXPECT_EQ(ring.front().y(), ring.back().y());
    // Linear between samples 0.05 apart: within the interpolation's error of the true circle.
    for (const Vec2& p : ring) EXPECT_NEAR(std::hypot(p.x(), p.y()), std::sqrt(0.5), 2e-3);
    // A missing value on the ring's way cuts it open where its four squares are.
    z[30 * 41 + 20] = NAN;  // (0.5, 0): near radius 0.707
    z[20 * 41 + 34] = NAN;  // (0, 0.7)
    lines = render::contour_lines(xs, ys, z, 0.5);
    EXPECT_EQ(lines.size(), 1u);  // still one line, now open: one gap at (0, 0.7); (0.5, 0) is inside the ring
    z[34 * 41 + 20] = NAN;  // (0.7, 0): a second gap
    lines = render::contour_lines(xs, ys, z, 0.5);
    EXPECT_EQ(lines.size(), 2u);
    for (const auto& l : lines)
        for (const Vec2& p : l) EXPECT_GT(std::hypot(p.x(), p.y() - 0.7) + std::hypot(p.x() - 0.7, p.y()), 0.04);
}

TEST(GoldenMap, SmallHeatMapWithEveryKindOfCell) {
    SweepMap map;
    map.x = {"bench width", "m", steps(0.20, 0.40, 7), 0.30};
    map.y = MapAxis{"body board length", "m", steps(1.6, 2.8, 5), 2.2};
    map.note = "7 x 5 made-up values";
    MapPanel panel{"minimum pitch", "m", {}, {}};
    for (double w : map.x.values) {
        for (double b : map.y->values) {
            panel.values.push_back(w + 0.05 + 0.08 * b + 0.6 * (w - 0.3) * (w - 0.3));
            panel.cells.push_back(MapCell::value);
        }
    }
    const auto at = [&](int i, int j) { return static_cast<std::size_t>(i * 5 + j); };
    for (int j = 3; j < 5; ++j) panel.cells[at(6, j)] = MapCell::jam, panel.values[at(6, j)] = NAN;
    panel.cells[at(0, 0)] = MapCell::refused, panel.values[at(0, 0)] = NAN;
    panel.cells[at(3, 4)] = MapCell::no_value, panel.values[at(3, 4)] = NAN;
    map.panels.push_back(panel);
    constexpr int w = 480, h = 320;
    cairo::Surface surface(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, w, h));
    cairo::Context cr = cairo::make_context(surface.get());
    test::outline_fonts(cr.get());
    draw_sweep_map(cr.get(), map, w, h);
    ASSERT_EQ(cairo_status(cr.get()), CAIRO_STATUS_SUCCESS);
    const auto r = test::compare_golden(surface.get(), "sweep_heat_map_7x5_jam_refused_novalue_mark_480x320.png");
    if (r.rebaselined) std::printf("%s\n", r.message.c_str());
    EXPECT_TRUE(r.ok) << r.message;
}

TEST(SweepMapOutput, PictureFormatsOnly) {
    EXPECT_NO_THROW(require_map_format("map.pdf"));
    EXPECT_THROW(require_map_format("map.jpg"), InputError);
    EXPECT_THROW(require_map_format("map"), InputError);
    EXPECT_NO_THROW(require_map_format("map.png"));
    EXPECT_NO_THROW(require_map_format("map.SVG"));
}

}  // namespace
}  // namespace dragon
