// Shapes cut to the picture and guides flattened only where the view is: exact where it shows,
// and work that follows the view, not the path's length.
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "render/cairo_handles.hpp"
#include "dragon/render.hpp"
#include "render/clip.hpp"
#include "render/guide.hpp"
#include "render/paint.hpp"

namespace dragon {
namespace {

using render::Box;

double area(const std::vector<Vec2>& poly) {
    double a = 0;
    for (std::size_t i = 0; i < poly.size(); ++i) a += cross(poly[i], poly[(i + 1) % poly.size()]);
    return 0.5 * std::abs(a);
}

bool inside(const Box& b, const Vec2& p, double slack = 1e-9) { return b.grown(slack).holds(p); }

TEST(Clip, PolygonIsCutToTheBox) {
    const Box box{{0, 0}, {10, 10}};
    // A square half outside on the right: the box keeps the 5 x 10 left half.
    const auto cut = render::clip_polygon({{5, 0}, {15, 0}, {15, 10}, {5, 10}}, box);
    EXPECT_NEAR(area(cut), 50.0, 1e-12);
    for (Vec2 p : cut) EXPECT_TRUE(inside(box, p));
    // Wholly inside: the same polygon; wholly outside: nothing.
    EXPECT_NEAR(area(render::clip_polygon({{1, 1}, {3, 1}, {2, 4}}, box)), 3.0, 1e-12);
    EXPECT_TRUE(render::clip_polygon({{20, 20}, {30, 20}, {25, 30}}, box).empty());
}

TEST(Clip, PolylineKeepsOnlyThePiecesInside) {
    const Box box{{0, 0}, {10, 10}};
    // In, out across the top, back in: two pieces, each ending on the box's edge.
    const auto pieces = render::clip_polyline({{2, 5}, {5, 15}, {8, 5}}, false, box);
    ASSERT_EQ(pieces.size(), 2u);
    EXPECT_NEAR(pieces[0].back().y(), 10.0, 1e-12);
    EXPECT_NEAR(pieces[1].front().y(), 10.0, 1e-12);
    EXPECT_NEAR(pieces[1].back().x(), 8.0, 1e-12);
    // A run inside stays one piece with all its points.
    const auto one = render::clip_polyline({{1, 1}, {2, 2}, {3, 1}, {4, 2}}, false, box);
    ASSERT_EQ(one.size(), 1u);
    EXPECT_EQ(one[0].size(), 4u);
}

// A circle a million times wider than the box, crossing it: the disk's part of the box, exact
// to the flattening tolerance, with a few dozen points.
TEST(Clip, HugeDiskCrossingTheBoxIsCutExactly) {
    const Box box{{0, 0}, {100, 100}};
    const double r = 1e8;
    const Vec2 c{50, -r + 50};  // its top passes through the box's middle, (50, 50)
    const auto disk = render::disk_in_box(c, r, box, 0.1);
    ASSERT_FALSE(disk.empty());
    EXPECT_LT(disk.size(), 200u);
    for (Vec2 p : disk) EXPECT_TRUE(inside(box, p));
    // Below the circle y = c.y() + sqrt(r^2 - (x - 50)^2) ~ 50 - (x - 50)^2 / (2 r), over 0..100.
    const double exact = 100 * 50 - (2 * std::pow(50.0, 3) / 3) / (2 * r);
    EXPECT_NEAR(area(disk), exact, 0.1 * 100);  // the tolerance along one 100 px edge at most
    const auto ring = render::circle_in_box(c, r, box, 0.1);
    ASSERT_EQ(ring.size(), 1u);
    for (Vec2 p : ring[0]) {
        EXPECT_TRUE(inside(box, p));
        EXPECT_NEAR(distance(p, c), r, 1e-6 * r);
    }
    // Far apart: nothing; the box inside the disk: the whole box.
    EXPECT_TRUE(render::disk_in_box({500, 500}, 10, box, 0.1).empty());
    EXPECT_NEAR(area(render::disk_in_box({50, 50}, 1e9, box, 0.1)), 1e4, 1e-6);
    EXPECT_TRUE(render::circle_in_box({50, 50}, 1e9, box, 0.1).empty());
}

// A Path that counts its evaluations.
class CountingPath final : public Path {
public:
    explicit CountingPath(const Path& p) : p_(p) {}
    mutable long evaluations = 0;
    Located at(Place p) const override { return ++evaluations, p_.at(p); }
    double arc(Place p) const override { return p_.arc(p); }
    Located at_arc(double s) const override { return ++evaluations, p_.at_arc(s); }
    double s_min() const override { return p_.s_min(); }
    double s_max() const override { return p_.s_max(); }
    double curvature(Place p) const override { return p_.curvature(p); }
    double turning(Place rear, Place front) const override { return p_.turning(rear, front); }
    double curvature_bounded_before(double k) const override { return p_.curvature_bounded_before(k); }
    double curvature_bounded_after(double k) const override { return p_.curvature_bounded_after(k); }
    double piece_begin(int piece) const override { return p_.piece_begin(piece); }
    std::pair<double, double> piece_span(int piece) const override { return p_.piece_span(piece); }
    std::pair<double, double> curvature_span(int piece) const override { return p_.curvature_span(piece); }
    std::optional<Located> behind(const Located& from, double chord) const override { return p_.behind(from, chord); }

private:
    const Path& p_;
};

// A millimetre box on the contest's spiral, 8.25 m out (theta = 30 pi): the ranges hold every
// point of the path inside the box, span little more than the box, and cost a few hundred
// evaluations for ~450 m of path (flattening all of it at the box's scale took 10^7).
TEST(Guide, ArcRangesInATinyBoxCoverItAndCostLittle) {
    const Spiral spiral(0.55);
    const CountingPath path(spiral);
    const double box_half = 5e-4;
    const Vec2 centre{0.55 * 15, 0.0};
    const Box box{{centre.x() - box_half, centre.y() - box_half}, {centre.x() + box_half, centre.y() + box_half}};
    const double s0 = -spiral.length_to(2 * std::numbers::pi * 20), s1 = spiral.s_max();
    const double resolution = 2 * box_half / 40;
    const auto ranges = render::arcs_in_box(path, s0, s1, box, resolution);
    EXPECT_LT(path.evaluations, 2000);
    double total = 0;
    for (auto [a, b] : ranges) total += b - a;
    EXPECT_LT(total, 4 * box_half + 4 * resolution);
    // The spiral crosses the box once, through its centre: at theta = 30 pi.
    const double s_centre = -spiral.length_to(30 * std::numbers::pi);
    bool covered = false;
    for (auto [a, b] : ranges) covered = covered || (a <= s_centre && s_centre <= b);
    EXPECT_TRUE(covered);
    // Every point of the path in the box lies in a range (sampled every 10 um near it).
    for (double s = s_centre - 0.01; s <= s_centre + 0.01; s += 1e-5) {
        if (!box.holds(spiral.at_arc(s).pos)) continue;
        bool in = false;
        for (auto [a, b] : ranges) in = in || (a <= s && s <= b);
        EXPECT_TRUE(in) << s;
    }
}

TEST(View, OnlyViewsDoublesCanDrawAreTaken) {
    EXPECT_EQ(check_view({0, 0}, 10, 10, 800, 800), ViewError::none);
    EXPECT_EQ(check_view({std::nan(""), 0}, 10, 10, 800, 800), ViewError::not_finite);
    EXPECT_EQ(check_view({0, 0}, INFINITY, 10, 800, 800), ViewError::not_finite);
    EXPECT_EQ(check_view({0, 0}, 1e-10, 1e-10, 800, 800), ViewError::too_narrow);
    EXPECT_EQ(check_view({0, 0}, 0, 10, 800, 800), ViewError::too_narrow);
    EXPECT_EQ(check_view({0, 0}, 1e9, 1e9, 800, 800), ViewError::too_wide);
    EXPECT_EQ(check_view({2e8, 0}, 1, 1, 800, 800), ViewError::too_far);
    // 8.8 m out, a pixel must be at least 8.8e-12 m: 800 px of it are 7.04e-9 m.
    EXPECT_EQ(check_view({8.8, 0}, 7e-9, 7e-9, 800, 800), ViewError::too_fine);
    EXPECT_EQ(check_view({8.8, 0}, 7.1e-9, 7.1e-9, 800, 800), ViewError::none);
    EXPECT_NEAR(narrowest_view({8.8, 0}, 800, 600), 8.8e-12 * 600, 1e-20);
    EXPECT_EQ(narrowest_view({0, 0}, 800, 600), kMinViewExtent);
}

TEST(Paint, ScaleLabelsUseTheUnitThatReads) {
    EXPECT_EQ(render::scale_label(2.0), "2 m");
    EXPECT_EQ(render::scale_label(0.5), "0.50 m");
    EXPECT_EQ(render::scale_label(0.005), "5 mm");
    EXPECT_EQ(render::scale_label(2e-4), "200 \u00b5m");
    EXPECT_EQ(render::scale_label(2e-9), "2 nm");
    EXPECT_EQ(render::scale_label(2e4), "20 km");
}

TEST(Paint, FittedTextFitsItsRoom) {
    cairo::Surface s(cairo_image_surface_create(CAIRO_FORMAT_RGB24, 8, 8));
    cairo::Context cr = cairo::make_context(s.get());
    const std::string font = "DejaVu Sans";
    const std::string text = "Exact rectangle distances. First contact at t = 412.473838 s (benches 1 and 9); "
                             "the paper's 0.1 s grid gives 413 s.";
    for (double room : {900.0, 600.0, 300.0}) {
        const auto fit = render::fit_text(cr.get(), font, 12, text, room);
        ASSERT_FALSE(fit.lines.empty());
        EXPECT_LE(fit.lines.size(), 2u) << room;
        std::string joined;
        for (const auto& line : fit.lines) {
            EXPECT_LE(render::text_width(cr.get(), font, fit.size, line), room) << room << ": " << line;
            joined += (joined.empty() ? "" : " ") + line;
        }
        EXPECT_EQ(joined, text);  // every word, in order
    }
    // Wide enough: one line at the size asked for.
    const auto roomy = render::fit_text(cr.get(), font, 12, "short", 500);
    EXPECT_EQ(roomy.lines.size(), 1u);
    EXPECT_EQ(roomy.size, 12.0);
}

}  // namespace
}  // namespace dragon
