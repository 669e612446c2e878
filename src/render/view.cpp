// The shapes drawn through a View: paths cut to the picture where they reach far outside it.
#include "view.hpp"

#include <algorithm>
#include <numbers>

namespace dragon::render {

namespace {
// Flattening tolerance of the arcs cut here, px (Cairo's own default).
constexpr double arc_tolerance = 0.1;

}  // namespace

void polygon_path(cairo_t* cr, const std::vector<Vec2>& pts) {
    if (pts.empty()) return;
    cairo_move_to(cr, pts[0].x(), pts[0].y());
    for (std::size_t i = 1; i < pts.size(); ++i) cairo_line_to(cr, pts[i].x(), pts[i].y());
    cairo_close_path(cr);
}

void rect_path(cairo_t* cr, const View& v, const Rect& r) {
    const Corners c = corners(r);
    std::vector<Vec2> pts;
    for (Vec2 p : c.p) pts.push_back(v.px(p));
    if (!std::all_of(pts.begin(), pts.end(), [&](const Vec2& p) { return v.tame.holds(p); }))
        pts = clip_polygon(std::move(pts), v.cut);
    polygon_path(cr, pts);
}

bool tame_circle(const View& v, const Vec2& p, double r) { return v.tame.grown(-r).holds(p); }
bool off_picture(const View& v, const Vec2& p, double r) { return !v.cut.grown(r).holds(p); }

// A disk of radius r px about p, to fill.
void circle_path(cairo_t* cr, const View& v, const Vec2& p, double r) {
    if (off_picture(v, p, r)) return;
    if (tame_circle(v, p, r)) {
        cairo_new_sub_path(cr);
        cairo_arc(cr, p.x(), p.y(), r, 0, 2 * std::numbers::pi);
    } else {
        polygon_path(cr, disk_in_box(p, r, v.cut, arc_tolerance));
    }
}

// The circle's outline, to stroke.
void ring_path(cairo_t* cr, const View& v, const Vec2& p, double r) {
    if (off_picture(v, p, r)) return;
    if (tame_circle(v, p, r)) {
        cairo_new_sub_path(cr);
        cairo_arc(cr, p.x(), p.y(), r, 0, 2 * std::numbers::pi);
        return;
    }
    for (const auto& piece : circle_in_box(p, r, v.cut, arc_tolerance)) {
        cairo_move_to(cr, piece[0].x(), piece[0].y());
        for (std::size_t i = 1; i < piece.size(); ++i) cairo_line_to(cr, piece[i].x(), piece[i].y());
    }
}

void set_dash(cairo_t* cr, bool dashed, double u) {
    if (dashed) {
        const double d[2] = {6 * u, 4 * u};
        cairo_set_dash(cr, d, 2, 0);
    } else {
        cairo_set_dash(cr, nullptr, 0, 0);
    }
}

// The part of the world the picture shows, widened by `pad_px` pixels on every side.
Box world_box(const View& v, double w, double h, double pad_px) {
    const double pad = pad_px / v.scale;
    return {{v.cx - v.ox / v.scale - pad, v.cy - (h - v.oy) / v.scale - pad},
            {v.cx + (w - v.ox) / v.scale + pad, v.cy + v.oy / v.scale + pad}};
}

}  // namespace dragon::render
