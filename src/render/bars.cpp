// The measuring furniture: the scale bar (bottom left), the colour bar of speeds (right) and the
// inset of the whole dragon (bottom right).
#include <algorithm>
#include <cmath>

#include "furniture.hpp"
#include "render/paint.hpp"
#include "render/words.hpp"

namespace dragon::render {

double colour_bar_room(const Scene& s, const Units& un) {
    // Wide enough for its numbers, which keep a readable size on small pictures.
    return (s.colour_by_speed && s.show_colour_bar) ? 110.0 * (s.show_text ? un.ut : un.u) : 0.0;
}

Box draw_scale_bar(cairo_t* cr, const Scene& s, const Units& un, double px_per_m) {
    if (!s.show_scale_bar) return {{0, un.h}, {0, un.h}};
    const double u = un.u;
    const double metres = nice_floor(0.2 * s.view_width);
    const double len = metres * px_per_m;
    const double x0 = 16 * u, y0 = un.h - 16 * u, tick = 5 * u, size = un.text(13);
    const double label_w = s.show_text ? text_width(cr, s.theme.font, size, scale_label(metres)) : 0.0;
    const double box_w = std::max(len, label_w) + 12 * u;
    const double box_h = s.show_text ? 18 * u + size + 4 * un.ut : 18 * u;
    backdrop(cr, s.theme, x0 - 6 * u, y0 + 6 * u - box_h, box_w, box_h);
    set_colour(cr, s.theme.text);
    cairo_set_line_width(cr, 2 * u);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_SQUARE);
    cairo_move_to(cr, x0, y0 - tick);
    cairo_line_to(cr, x0, y0);
    cairo_line_to(cr, x0 + len, y0);
    cairo_line_to(cr, x0 + len, y0 - tick);
    cairo_stroke(cr);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
    // Centred over the bar, or, wider than it, from its left end (inside its backdrop).
    if (s.show_text)
        text(cr, s.theme.font, size, x0 + 0.5 * std::max(len, label_w), y0 - 4 * u - 4 * un.ut, scale_label(metres), 0.5);
    return {{x0 - 6 * u, y0 + 6 * u - box_h}, {x0 - 6 * u + box_w, y0 + 6 * u}};
}

void draw_colour_bar(cairo_t* cr, const Scene& s, const Units& un, double room, double top) {
    if (room <= 0) return;
    const double u = un.u, ut = s.show_text ? un.ut : un.u;
    const double bar_w = 16 * u, x = un.w - room + 18 * ut;
    // y0 top (fast), y1 bottom (slow); the top clear of the clock and of the bar's own title.
    const double y0 = std::max(0.18 * un.h, top + 34 * ut), y1 = std::max(y0 + 40 * u, 0.82 * un.h);
    // The strip is the bar's own (draw() keeps the drawing out of it): no backdrop needed.
    cairo_pattern_t* grad = cairo_pattern_create_linear(0, y1, 0, y0);
    const auto& stops = s.theme.speed_ramp;
    for (std::size_t i = 0; i < stops.size(); ++i) {
        const double t = stops.size() > 1 ? double(i) / double(stops.size() - 1) : 0.0;
        cairo_pattern_add_color_stop_rgba(grad, t, stops[i].r, stops[i].g, stops[i].b, stops[i].a);
    }
    cairo_rectangle(cr, x, y0, bar_w, y1 - y0);
    cairo_set_source(cr, grad);
    cairo_fill_preserve(cr);
    cairo_pattern_destroy(grad);
    set_colour(cr, s.theme.text);
    cairo_set_line_width(cr, 1 * u);
    cairo_stroke(cr);
    if (!s.show_text) return;
    const auto ticks = nice_ticks(s.speed_min, s.speed_max, 5);
    for (double t : ticks.values) {
        const double y = y1 - (t - s.speed_min) / (s.speed_max - s.speed_min) * (y1 - y0);
        cairo_move_to(cr, x + bar_w, y);
        cairo_line_to(cr, x + bar_w + 4 * u, y);
        cairo_stroke(cr);
        text(cr, s.theme.font, un.text(11), x + bar_w + 6 * u, y, format_tick(t, ticks.decimals), 0.0, 0.5);
    }
    text(cr, s.theme.font, un.text(12), un.w - 0.5 * room - 3 * ut, y0 - 14 * ut, words(s.language).speed_axis, 0.5);
}

Box draw_inset(cairo_t* cr, const Scene& s, const Units& un, double right, const Vec2& lo, const Vec2& hi) {
    if (!s.inset) return {{right, un.h}, {right, un.h}};
    Scene inset = *s.inset;
    inset.show_text = false;
    const double side = std::round(0.3 * std::min(un.w, un.h));
    // Two pixels wide whatever the inset's size (a polyline's width scales with its picture).
    Polyline box{{lo, {hi.x(), lo.y()}, hi, {lo.x(), hi.y()}}, s.theme.collision, 2.0 / Units::of(side, side).u};
    box.closed = true;
    inset.polylines.push_back(std::move(box));
    const double x = std::round(right - 10 * un.u - side), y = std::round(un.h - 10 * un.u - side);
    cairo_save(cr);
    cairo_translate(cr, x, y);
    cairo_rectangle(cr, 0, 0, side, side);
    cairo_clip(cr);
    draw(cr, inset, static_cast<int>(side), static_cast<int>(side));
    cairo_restore(cr);
    set_colour(cr, s.theme.text);
    cairo_set_line_width(cr, 1.5 * un.u);
    cairo_rectangle(cr, x - 0.75 * un.u, y - 0.75 * un.u, side + 1.5 * un.u, side + 1.5 * un.u);
    cairo_stroke(cr);
    return {{x - 0.75 * un.u, y - 0.75 * un.u}, {x + side + 0.75 * un.u, y + side + 0.75 * un.u}};
}

}  // namespace dragon::render
