// Marks drawn over the dragon: polylines and arrows, markers, the contact.
#include <algorithm>
#include <vector>

#include "render/paint.hpp"
#include "view.hpp"

namespace dragon::render {

namespace {
void draw_marker(cairo_t* cr, const View& v, const Marker& m, const Vec2& p, double u) {
    if (off_picture(v, p, m.radius_px * u)) return;
    set_colour(cr, m.colour);
    if (m.ring) {
        ring_path(cr, v, p, m.radius_px * u);
        cairo_set_line_width(cr, 1.5 * u);
        cairo_stroke(cr);
    } else {
        circle_path(cr, v, p, m.radius_px * u);
        cairo_fill(cr);
    }
}

}  // namespace

void draw_collision(cairo_t* cr, const Scene& s, const View& v, double u) {
    if (!s.collision) return;
    const Vec2 p = v.px(s.collision->point);
    draw_marker(cr, v, {s.collision->point, s.theme.contact, 9.0, true}, p, u);
    draw_marker(cr, v, {s.collision->point, s.theme.contact, 2.2, false}, p, u);
}

void draw_overlays(cairo_t* cr, const Scene& s, const View& v, double u) {
    for (const auto& pl : s.polylines) {
        if (pl.points.empty()) continue;
        const std::size_t last = pl.points.size() - 1;
        // With an arrowhead the line stops inside the head, so its square end cannot poke out
        // beside the tip.
        const double head = (4 + 2.5 * pl.width_px) * u;
        Vec2 tip = Vec2::Zero(), dir = Vec2::Zero();
        const bool arrow = pl.arrow && last >= 1 && norm(v.px(pl.points[last]) - v.px(pl.points[last - 1])) > 0;
        if (arrow) {
            tip = v.px(pl.points[last]);
            dir = normalized(tip - v.px(pl.points[last - 1]));
        }
        std::vector<Vec2> pts;
        for (std::size_t i = 0; i <= last; ++i) pts.push_back(v.px(pl.points[i]));
        if (arrow) pts[last] = tip - 0.7 * head * dir;
        if (std::all_of(pts.begin(), pts.end(), [&](const Vec2& p) { return v.tame.holds(p); })) {
            for (std::size_t i = 0; i <= last; ++i) {
                if (i == 0) cairo_move_to(cr, pts[i].x(), pts[i].y());
                else cairo_line_to(cr, pts[i].x(), pts[i].y());
            }
            if (pl.closed) cairo_close_path(cr);
        } else {
            for (const auto& piece : clip_polyline(pts, pl.closed, v.cut)) {
                cairo_move_to(cr, piece[0].x(), piece[0].y());
                for (std::size_t i = 1; i < piece.size(); ++i) cairo_line_to(cr, piece[i].x(), piece[i].y());
            }
        }
        set_colour(cr, pl.colour);
        cairo_set_line_width(cr, pl.width_px * u);
        set_dash(cr, pl.dashed, u);
        cairo_stroke(cr);
        if (arrow && !off_picture(v, tip, head)) {
            const Vec2 n = perp(dir);
            const Vec2 a = tip - head * dir + 0.45 * head * n, b = tip - head * dir - 0.45 * head * n;
            cairo_move_to(cr, tip.x(), tip.y());
            cairo_line_to(cr, a.x(), a.y());
            cairo_line_to(cr, b.x(), b.y());
            cairo_close_path(cr);
            cairo_fill(cr);
        }
    }
    set_dash(cr, false, u);
    for (const auto& m : s.markers) draw_marker(cr, v, m, v.px(m.pos), u);
}

}  // namespace dragon::render
