// draw(): paints a Scene onto any Cairo context. Raster surfaces get one fill per style group
// (a few path operations for the whole dragon); vector surfaces get one shape per bench so an
// SVG stays editable bench by bench.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "dragon/render.hpp"
#include "furniture.hpp"
#include "backdrop_key.hpp"
#include "guide.hpp"
#include "labels.hpp"
#include "view.hpp"
#include "render/paint.hpp"

namespace dragon {

namespace {

using render::set_colour;
using namespace render;  // View and its shapes


// The view fits the picture less the colour bar's strip on the right and the title band on
// top. Cut shapes keep a margin wider than any line outside the picture, so no cut edge shows.
// Where the picture is wider than the view needs (a whole dragon in a 16:9 frame), the view
// moves right of the title and legend at the top left (left_room), so they cover none of it.
View make_view(const Scene& s, double w, double h, double right_room, double top_room, double left_room, double u) {
    const double avail = std::max(1.0, w - right_room), avail_h = std::max(1.0, h - top_room);
    const double scale = std::min(avail / s.view_width, avail_h / s.view_height);
    const render::Box picture{{0, 0}, {w, h}};
    double cx = 0.5 * avail;
    const double shown = s.view_width * scale, margin = 6 * u;
    if (left_room > 0 && shown + left_room + margin <= avail) cx = std::max(cx, left_room + margin + 0.5 * shown);
    return {s.view_centre.x(), s.view_centre.y(), scale, cx, top_room + 0.5 * avail_h,
            picture.grown(4 * (w + h)), picture.grown(32 * u)};
}


Rgba style_colour(const Scene& s, const Scene::Bench& b) {
    switch (b.style) {
    case Scene::Style::highlight: return s.theme.highlight;
    case Scene::Style::collision: return s.theme.collision;
    default: break;
    }
    if (s.colour_by_speed) {
        double t = (b.speed - s.speed_min) / (s.speed_max - s.speed_min);
        t = std::clamp(t, 0.0, 1.0);
        return render::ramp_colour(s.theme.speed_ramp, t);
    }
    switch (b.style) {
    case Scene::Style::head: return s.theme.head;
    case Scene::Style::tail: return s.theme.tail;
    default: return s.theme.body;
    }
}

void draw_turning_space(cairo_t* cr, const Scene& s, const View& v, double u) {
    if (!s.turning_radius) return;
    const Vec2 c = v.px({0, 0});
    const double r = *s.turning_radius * v.scale;
    circle_path(cr, v, c, r);
    set_colour(cr, s.theme.turning_fill);
    cairo_fill(cr);
    ring_path(cr, v, c, r);
    set_colour(cr, s.theme.turning_space);
    cairo_set_line_width(cr, 1.5 * u);
    set_dash(cr, true, u);
    cairo_stroke(cr);
    set_dash(cr, false, u);
}


// Bezier segments the guides may use in one picture: far more than a coiled dragon needs (about
// 2,000 at any size), and few enough that a path packed tighter than the pixels costs what
// the picture's size allows rather than what the path's length asks.
double guide_budget(double w, double h) { return 20.0 * (w + h); }

// Guides are flattened only where the picture shows them: the arc ranges that come within the
// picture's box, at steps of a fortieth of its extent, so a close-up of a long path costs what
// it shows. They are stroked in short runs: a stroke's cost follows the rows its bounding box
// covers, and a whole spiral covers the picture. A quarter-pixel flattening tolerance is
// invisible on a one-pixel line and halves the segments.
void draw_guides(cairo_t* cr, const Scene& s, const View& v, double u, double w, double h) {
    const render::Box box = world_box(v, w, h, 8 * u);
    const double extent = box.extent();
    std::vector<std::vector<std::pair<double, double>>> ranges;
    double shown = 0;  // arc length of the guides in the picture, m
    for (const auto& g : s.guides) {
        ranges.push_back(g.path ? render::arcs_in_box(*g.path, g.s0, g.s1, box, extent / 40.0)
                                : std::vector<std::pair<double, double>>{});
        for (auto [a, b] : ranges.back()) shown += b - a;
    }
    const double budget_step = shown / guide_budget(w, h);
    const double max_step = std::max(extent / 40.0, budget_step);
    const double min_step = std::max(0.5 / v.scale, budget_step);  // half a pixel

    constexpr std::size_t run = 12;  // Bezier segments per stroke
    cairo_save(cr);
    cairo_set_tolerance(cr, 0.25);
    for (std::size_t i = 0; i < s.guides.size(); ++i) {
        const auto& g = s.guides[i];
        set_colour(cr, g.colour);
        cairo_set_line_width(cr, g.width_px * u);
        set_dash(cr, g.dashed, u);
        for (auto [a, b] : ranges[i]) {
            for (const auto& r : render::path_beziers(*g.path, a, b, max_step, 0.3, min_step)) {
                const std::vector<Vec2>& z = r.beziers;
                const std::size_t segments = (z.size() - 1) / 3;
                for (std::size_t k = 0; k < segments; ++k) {
                    if (k % run == 0) {
                        const Vec2 p = v.px(z[3 * k]);
                        cairo_move_to(cr, p.x(), p.y());
                    }
                    const Vec2 p1 = v.px(z[3 * k + 1]), p2 = v.px(z[3 * k + 2]), p3 = v.px(z[3 * k + 3]);
                    cairo_curve_to(cr, p1.x(), p1.y(), p2.x(), p2.y(), p3.x(), p3.y());
                    if (k % run == run - 1 || k + 1 == segments) cairo_stroke(cr);
                }
            }
        }
    }
    cairo_restore(cr);
}

// Is any part of the rectangle possibly on screen? (A cheap box test; culling matters for
// close-up views of a long dragon.)
bool on_screen(const View& v, const Rect& r, double w, double h) {
    const Vec2 c = v.px(r.centre);
    const double reach = (r.half_length + r.half_width) * v.scale;
    return c.x() + reach >= 0 && c.x() - reach <= w && c.y() + reach >= 0 && c.y() - reach <= h;
}

// A bench's corners in pixels, in order around it (rear right, front right, front left, rear left).
std::vector<Vec2> corners_px(const View& v, const Rect& r) {
    const Vec2 a = r.half_length * r.axis, c = r.half_width * Vec2{-r.axis.y(), r.axis.x()};
    return {v.px(r.centre - a - c), v.px(r.centre + a - c), v.px(r.centre + a + c), v.px(r.centre - a + c)};
}

Rect inset(Rect r, double by) {
    r.half_length = std::max(0.0, r.half_length - by);
    r.half_width = std::max(0.0, r.half_width - by);
    return r;
}

// Raster surfaces: each bench as two fills, the outline colour over the whole rectangle and
// its own colour over the rectangle inset by the outline width. Fills only, because Cairo's
// stroker costs several fills; and one small fill per bench, because the scan converter's cost
// follows the rows and edges of each fill's bounding box: measured on a 1080p frame, 223 single
// fills take 2.4 ms, one fill of all 223 rectangles 6.2 ms. Drawn in order, so at every joint
// the next board lies on the one before, as on the real dragon.
void draw_benches_raster(cairo_t* cr, const Scene& s, const View& v, double outline_px, double w, double h) {
    const double in = outline_px / v.scale;
    for (const auto& b : s.benches) {
        if (!on_screen(v, b.rect, w, h)) continue;
        rect_path(cr, v, b.rect);
        set_colour(cr, s.theme.outline);
        cairo_fill(cr);
        rect_path(cr, v, inset(b.rect, in));
        set_colour(cr, style_colour(s, b));
        cairo_fill(cr);
    }
}

// Vector surfaces: each bench one shape, filled and outlined (an SVG stays editable bench by
// bench).
void draw_benches_vector(cairo_t* cr, const Scene& s, const View& v, double outline_px, double w, double h) {
    cairo_set_line_width(cr, outline_px);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_MITER);
    for (const auto& b : s.benches) {
        if (!on_screen(v, b.rect, w, h)) continue;
        rect_path(cr, v, b.rect);
        set_colour(cr, style_colour(s, b));
        cairo_fill_preserve(cr);
        set_colour(cr, s.theme.outline);
        cairo_stroke(cr);
    }
}

void draw_benches(cairo_t* cr, const Scene& s, const View& v, double u, bool vector_surface, double w, double h) {
    if (s.benches.empty()) return;
    const double bench_px = 2 * s.benches.front().rect.half_width * v.scale;
    const double outline_px = std::clamp(0.12 * bench_px, 0.3 * u, 1.2 * u);
    if (vector_surface) draw_benches_vector(cr, s, v, outline_px, w, h);
    else draw_benches_raster(cr, s, v, outline_px, w, h);

    // Touching and highlighted benches drawn again on top: they must never hide under a
    // neighbour.
    cairo_set_line_width(cr, std::max(outline_px, 1.0 * u));
    for (const auto& b : s.benches) {
        if (b.style != Scene::Style::collision && b.style != Scene::Style::highlight) continue;
        rect_path(cr, v, b.rect);
        if (render::layout_recording()) {
            // The touching benches, nothing may cover them: logged as a grid of points over the
            // board, 16 along and 3 across (a slanted board's box would claim the corners beside it).
            const std::vector<Vec2> q = corners_px(v, b.rect);
            for (int k = 0; k < 16; ++k)
                for (int j = 0; j < 3; ++j) {
                    const double f = (k + 0.5) / 16.0, g = (j + 0.5) / 3.0;
                    const Vec2 m = (1 - g) * (q[0] + f * (q[1] - q[0])) + g * (q[3] + f * (q[2] - q[3]));
                    render::log_placed(cr, render::LayoutItem::Kind::mark, m.x(), m.y(), m.x(), m.y(), "touching bench");
                }
        }
        set_colour(cr, style_colour(s, b));
        cairo_fill_preserve(cr);
        set_colour(cr, s.theme.outline);
        cairo_stroke(cr);
    }
    if (s.colour_by_speed) {  // the head stays recognisable under the colour map
        rect_path(cr, v, s.benches.front().rect);
        set_colour(cr, s.theme.head);
        cairo_set_line_width(cr, std::max(2 * outline_px, 1.5 * u));
        cairo_stroke(cr);
    }
}

// One path for all handles, in every surface: they are markers, not objects to edit.
void draw_handles(cairo_t* cr, const Scene& s, const View& v, double u) {
    if (!s.show_handles || s.handles.empty()) return;
    const double bench_px = s.benches.empty() ? 4 * u : 2 * s.benches.front().rect.half_width * v.scale;
    const double r = std::min(std::max(s.handle_radius * v.scale, 1.1 * u), 0.3 * bench_px);
    set_colour(cr, s.theme.handle);
    if (r < 3.0) {
        // A dot a few pixels across: an octagon looks the same and skips flattening four
        // Bezier arcs per dot (a fifth of the cost).
        for (Vec2 h : s.handles) {
            const Vec2 c = v.px(h);
            if (off_picture(v, c, r)) continue;
            for (int i = 0; i < 8; ++i) {
                const double a = (i + 0.5) * std::numbers::pi / 4;
                const double x = c.x() + r * std::cos(a), y = c.y() + r * std::sin(a);
                if (i == 0) cairo_move_to(cr, x, y);
                else cairo_line_to(cr, x, y);
            }
            cairo_close_path(cr);
        }
    } else {
        for (Vec2 h : s.handles) circle_path(cr, v, v.px(h), r);
    }
    cairo_fill(cr);
}

// The scene, its backdrop (background, turning space, guides) copied from `cache` where it
// holds this one (nullptr: always drawn).
void draw_scene(cairo_t* cr, const Scene& s, int width_px, int height_px, render::BackdropCache* cache) {
    const render::Units un = render::Units::of(width_px, height_px, s.text_px);
    const double w = un.w, h = un.h, u = un.u;
    cairo_save(cr);
    cairo_set_antialias(cr, CAIRO_ANTIALIAS_DEFAULT);
    cairo_new_path(cr);

    // Measured only (nothing is drawn before the background).
    const bool vector_surface = cairo_surface_get_type(cairo_get_target(cr)) != CAIRO_SURFACE_TYPE_IMAGE;
    const double right = render::colour_bar_room(s, un);
    const double top = s.title_band ? render::annotation_height(cr, s, un, w) : 0.0;
    const double left = render::left_furniture(cr, s, un, s.title_band ? w : w - right);
    const View v = make_view(s, w, h, right, top, left, u);

    std::optional<render::BackdropKey> key;
    if (cache) key = render::backdrop_key(cr, s, v, u, top, right, width_px, height_px);
    const bool copied = key && render::copy_backdrop(cr, *cache, *key);
    if (!copied) {
        set_colour(cr, {s.theme.background.r, s.theme.background.g, s.theme.background.b, 1.0});
        cairo_set_operator(cr, CAIRO_OPERATOR_SOURCE);
        cairo_paint(cr);
        cairo_set_operator(cr, CAIRO_OPERATOR_OVER);
    }

    // The world runs under the furniture in the corners (no hard edge there); a title band and
    // the colour bar's strip are kept clear, the view fitting beside them: under the strip's
    // backdrop the outer coils would show dimmed, as if they were something else.
    cairo_save(cr);
    if (top > 0 || right > 0) {
        cairo_rectangle(cr, 0, top, w - right, h - top);
        cairo_clip(cr);
    }
    if (!copied) {
        draw_turning_space(cr, s, v, u);
        draw_guides(cr, s, v, u, w - right, h);
        if (key) render::keep_backdrop(cr, *cache, std::move(*key));
    }
    draw_benches(cr, s, v, u, vector_surface, w - right, h);
    draw_handles(cr, s, v, u);
    draw_collision(cr, s, v, u);
    draw_overlays(cr, s, v, u);
    cairo_restore(cr);

    // The furniture, each piece keeping clear of the ones before; labels then keep clear of all.
    const render::Box bar = render::draw_scale_bar(cr, s, un, v.scale);
    const render::Box clock = render::draw_clock(cr, s, un, w - right);
    render::draw_colour_bar(cr, s, un, right, std::max(clock.hi.y(), top));
    const render::Box shown = world_box(v, w - right, h, 0.0);
    const render::Box inset = render::draw_inset(cr, s, un, w - right, shown.lo, shown.hi);
    // A title band spans the picture; an annotation over the drawing keeps clear of the clock.
    // Beside the clock where it leaves room for a line of some words; else under the clock, across
    // the picture (a narrow frame: a film's split view).
    const bool under_clock = !s.title_band && clock.lo.x() < 0.55 * w && clock.hi.y() > clock.lo.y();
    const render::Box note = render::draw_annotation(cr, s, un, s.title_band || under_clock ? w - right : clock.lo.x(),
                                                     under_clock ? clock.hi.y() : 0.0);
    // What the legend explains and must not cover: the touching (and singled-out) benches.
    std::vector<std::vector<Vec2>> marks;
    for (const auto& b : s.benches)
        if (b.style == Scene::Style::collision || b.style == Scene::Style::highlight) marks.push_back(corners_px(v, b.rect));
    const render::Box legend = render::draw_legend(cr, s, un, std::max(note.hi.y(), 2 * u), marks, {bar, clock, inset},
                                                   w - right);
    const render::Box strip{{w - right, 0}, {w, h}};
    render::draw_labels(cr, s, un, [&v](const Vec2& p) { return v.px(p); }, {bar, clock, inset, note, legend, strip},
                        {{0, top}, {w, h}});
    const double scale_top = s.show_scale_bar ? h - 48 * un.ut : h;
    render::draw_captions(cr, s, un, bar.hi.x(), inset.lo.x(), std::min(scale_top, inset.lo.y()));
    cairo_restore(cr);
}

}  // namespace

void draw(cairo_t* cr, const Scene& s, int width_px, int height_px) { draw_scene(cr, s, width_px, height_px, nullptr); }

void render::draw_reusing_backdrop(cairo_t* cr, const Scene& s, int width_px, int height_px, BackdropCache& cache) {
    draw_scene(cr, s, width_px, height_px, &cache);
}

}  // namespace dragon
