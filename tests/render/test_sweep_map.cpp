// Maps of a sweep: contour lines by marching squares (on a plane exactly where it has the
// level; around a bowl one closed ring; none through a square without a value), and a golden
// image of a small heat map with its contour lines, colour bar, a cell of every kind that is not
// a value (cut short, refused, overlapping at the start, the answer below or above the range, no
// answer), and the contest's dragon marked. Text is drawn in the pinned DejaVu Sans.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <optional>

#include "render/cairo_handles.hpp"
#include "dragon/sweep_map.hpp"
#include "golden.hpp"
#include "render/contours.hpp"
#include "render/map_panels.hpp"
#include "dragon/plot.hpp"

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
    panel.cells[at(1, 0)] = MapCell::below_range, panel.values[at(1, 0)] = NAN;
    panel.cells[at(5, 4)] = MapCell::above_range, panel.values[at(5, 4)] = NAN;
    panel.cells[at(0, 4)] = MapCell::overlapping, panel.values[at(0, 4)] = NAN;
    map.panels.push_back(panel);
    constexpr int w = 480, h = 320;
    cairo::Surface surface(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, w, h));
    cairo::Context cr = cairo::make_context(surface.get());
    test::outline_fonts(cr.get());
    draw_sweep_map(cr.get(), map, w, h);
    ASSERT_EQ(cairo_status(cr.get()), CAIRO_STATUS_SUCCESS);
    const auto r = test::compare_golden(surface.get(), "sweep_heat_map_7x5_every_cell_kind_mark_480x320.png");
    if (r.rebaselined) std::printf("%s\n", r.message.c_str());
    EXPECT_TRUE(r.ok) << r.message;
}

// A plot's band for marks without a value lies under the data area, outside the value axis,
// and maps x as the data area does.
TEST(PlotStrip, UnderTheValuesSharingTheXAxis) {
    Plot p;
    p.series.push_back({"", {Vec2(0.0, 200.0), Vec2(1.0, 450.0)}, {0, 0, 1}});
    p.strip_px = 24;
    p.strip_label = "no value";
    std::optional<PlotArea> band;
    p.strip = [&](cairo_t*, const PlotArea& b, double) { band = b; };
    cairo::Surface surface(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 600, 400));
    cairo::Context cr = cairo::make_context(surface.get());
    const PlotArea a = draw_plot(cr.get(), p, 0, 0, 600, 400);
    ASSERT_TRUE(band.has_value());
    EXPECT_GT(band->y0, a.y1);
    EXPECT_GT(band->y1, band->y0);
    for (double x : {0.0, 0.3, 1.0}) EXPECT_DOUBLE_EQ(band->px(x), a.px(x));
}

// On a line plot every scenario without a value is a marker under the values' frame, outside
// the value axis (a dot at "195 s" inside the frame would read as a first contact).
TEST(LineMap, ScenariosWithoutAValueAreMarkedOutsideTheValueAxis) {
    SweepMap map;
    map.x = {"pitch", "m", steps(0.1, 0.9, 9), std::nullopt};
    MapPanel panel{"first contact", "s", {}, {}};
    for (double x : map.x.values) {
        const bool refused = x < 0.35, jam = x > 0.75;
        panel.values.push_back(refused || jam ? NAN : 200.0 + 500.0 * (x - 0.4));
        panel.cells.push_back(refused ? MapCell::refused : jam ? MapCell::jam : MapCell::value);
    }
    map.panels.push_back(panel);
    const auto [w, h] = sweep_map_size(map);
    cairo::Surface surface(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, w, h));
    cairo::Context cr = cairo::make_context(surface.get());
    draw_sweep_map(cr.get(), map, w, h);
    cairo_surface_flush(surface.get());
    // The value line's colour and the markers': the lowest pixel of the one, the highest of the others.
    const Rgba line = series_colour(map.theme, 0);
    const Rgba marker = render::cell_style(map.theme, MapCell::refused, panel).marker;
    const auto is = [](std::uint32_t px, const Rgba& c) {
        const auto ch = [&](int shift, double v) { return std::abs(static_cast<int>((px >> shift) & 0xff) - static_cast<int>(std::lround(v * 255))) <= 2; };
        return ch(16, c.r) && ch(8, c.g) && ch(0, c.b);
    };
    const unsigned char* data = cairo_image_surface_get_data(surface.get());
    const int stride = cairo_image_surface_get_stride(surface.get());
    // A dot's inside: the colour over 3 x 3 pixels (text's anti-aliased edges and thin lines are
    // never that solid), the value line's dots and the markers alike.
    const auto solid = [&](int x, int y, const Rgba& c) {
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx)
                if (!is(*reinterpret_cast<const std::uint32_t*>(data + (y + dy) * stride + 4 * (x + dx)), c)) return false;
        return true;
    };
    int lowest_line = -1, highest_marker = h, markers = 0;
    // Above the legend under the plot (whose swatches are markers too).
    for (int y = 1; y < h - 60; ++y)
        for (int x = 1; x + 1 < w; ++x) {
            if (solid(x, y, line)) lowest_line = std::max(lowest_line, y);
            if (solid(x, y, marker)) highest_marker = std::min(highest_marker, y), ++markers;
        }
    ASSERT_GE(lowest_line, 0);
    ASSERT_GT(markers, 0);
    EXPECT_GT(highest_marker, lowest_line);
    // And a frame's edge runs between them: the markers are outside the values' frame, not at
    // the bottom of it.
    bool edge = false;
    for (int y = lowest_line + 1; y < highest_marker && !edge; ++y) {
        int run = 0;
        for (int x = 0; x < w && !edge; ++x) {
            run = is(*reinterpret_cast<const std::uint32_t*>(data + y * stride + 4 * x), map.theme.text) ? run + 1 : 0;
            edge = run > w / 2;
        }
    }
    EXPECT_TRUE(edge) << "no frame edge between the lowest value (y " << lowest_line << ") and the markers (y "
                      << highest_marker << ")";
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
