// A heat map panel: one coloured cell per scenario over two varied values, contour lines through
// the values, a colour bar with the unit, cells without a value shown as such, and the
// contest's dragon marked.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include <fmt/format.h>

#include "dragon/plot.hpp"
#include "contours.hpp"
#include "map_panels.hpp"
#include "render/words.hpp"
#include "render/paint.hpp"

namespace dragon::render {

namespace {

// Cell edges: halfway between neighbouring values, and as far again beyond the first and last.
std::vector<double> edges(const std::vector<double>& v) {
    std::vector<double> e(v.size() + 1);
    if (v.size() == 1) {
        const double half = v[0] == 0.0 ? 0.5 : 0.05 * std::abs(v[0]);
        return {v[0] - half, v[0] + half};
    }
    for (std::size_t k = 1; k < v.size(); ++k) e[k] = 0.5 * (v[k - 1] + v[k]);
    e.front() = v.front() - (e[1] - v.front());
    e.back() = v.back() + (v.back() - e[v.size() - 1]);
    return e;
}

std::string capitalised(std::string s) {
    if (!s.empty() && s[0] >= 'a' && s[0] <= 'z') s[0] = static_cast<char>(s[0] - 'a' + 'A');
    return s;
}

// The map's values on sorted axes.
struct Sorted {
    std::vector<double> xs, ys, z;  // z[i * ny + j], NaN where the cell is no value
    std::vector<MapCell> cells;
    double lo = 0.0, hi = 1.0;      // the values' range
    bool any = false;
};

Sorted sort_panel(const SweepMap& map, const MapPanel& panel) {
    const std::vector<std::size_t> ox = sorted_order(map.x.values), oy = sorted_order(map.y->values);
    const std::size_t nx = ox.size(), ny = oy.size();
    Sorted s;
    for (std::size_t i : ox) s.xs.push_back(map.x.values[i]);
    for (std::size_t j : oy) s.ys.push_back(map.y->values[j]);
    s.z.assign(nx * ny, NAN);
    s.cells.assign(nx * ny, MapCell::missing);
    double lo = INFINITY, hi = -INFINITY;
    for (std::size_t i = 0; i < nx; ++i) {
        for (std::size_t j = 0; j < ny; ++j) {
            const std::size_t from = ox[i] * ny + oy[j], to = i * ny + j;
            s.cells[to] = panel.cells[from];
            if (panel.cells[from] != MapCell::value || !std::isfinite(panel.values[from])) continue;
            s.z[to] = panel.values[from];
            lo = std::min(lo, s.z[to]), hi = std::max(hi, s.z[to]);
        }
    }
    s.any = hi >= lo;
    if (s.any) s.lo = lo, s.hi = hi;
    if (s.any && s.hi - s.lo < 1e-12 * std::max(1.0, std::abs(s.lo))) s.lo -= 0.5, s.hi += 0.5;  // a flat map
    return s;
}

void draw_colour_bar(cairo_t* cr, const Theme& th, const MapPanel& panel, const Sorted& s, const Ticks& ticks,
                     const std::vector<double>& levels, const PlotArea& a, double x, double u, double body) {
    const auto T = [&](double n) { return text_size(n, u, body); };
    const double bw = 16 * u, y0 = a.y0, y1 = a.y1;
    const auto py = [&](double v) { return y1 - (v - s.lo) / (s.hi - s.lo) * (y1 - y0); };
    constexpr int kSteps = 128;
    for (int k = 0; k < kSteps; ++k) {
        set_colour(cr, ramp_colour(th.speed_ramp, (k + 0.5) / kSteps));
        const double ya = y1 - (y1 - y0) * (k + 1) / kSteps, yb = y1 - (y1 - y0) * k / kSteps;
        cairo_rectangle(cr, x, ya - 0.5, bw, yb - ya + 1.0);  // overlapping by a pixel: no seams
        cairo_fill(cr);
    }
    set_colour(cr, th.text);
    cairo_set_line_width(cr, 1.0 * u);
    cairo_rectangle(cr, x, y0, bw, y1 - y0);
    cairo_stroke(cr);
    // The contour levels across the bar, so each line can be read off it.
    set_colour(cr, {th.text.r, th.text.g, th.text.b, 0.7});
    for (double v : levels) cairo_move_to(cr, x, py(v)), cairo_line_to(cr, x + bw, py(v));
    cairo_stroke(cr);
    set_colour(cr, th.text);
    double widest = 0;
    for (double v : ticks.values) {
        if (v < s.lo - 1e-9 * (s.hi - s.lo) || v > s.hi + 1e-9 * (s.hi - s.lo)) continue;
        cairo_move_to(cr, x + bw, py(v));
        cairo_line_to(cr, x + bw + 4 * u, py(v));
        cairo_stroke(cr);
        const std::string label = format_tick(v, ticks.decimals);
        text(cr, th.font, T(12), x + bw + 7 * u, py(v), label, 0.0, 0.5);
        widest = std::max(widest, text_width(cr, th.font, T(12), label));
    }
    cairo_save(cr);
    cairo_translate(cr, x + bw + 16 * u + widest, 0.5 * (y0 + y1));
    cairo_rotate(cr, std::numbers::pi / 2);
    text(cr, th.font, T(13), 0, 0, axis_label(panel.quantity, panel.unit), 0.5);
    cairo_restore(cr);
}

// The cells of one kind other than values, filled and hatched as their style says.
void draw_other_cells(cairo_t* cr, const Theme& th, const MapPanel& panel, const Sorted& s, MapCell kind,
                      const std::vector<double>& ex, const std::vector<double>& ey, const PlotArea& a, double u) {
    const std::size_t ny = s.ys.size();
    bool any = false;
    for (std::size_t k = 0; k < s.cells.size(); ++k) {
        if (s.cells[k] != kind) continue;
        const std::size_t i = k / ny, j = k % ny;
        cairo_rectangle(cr, a.px(ex[i]), a.py(ey[j + 1]), a.px(ex[i + 1]) - a.px(ex[i]), a.py(ey[j]) - a.py(ey[j + 1]));
        any = true;
    }
    if (!any) return;
    const CellStyle st = cell_style(th, kind, panel);  // fill and hatching: no words
    cairo_save(cr);
    cairo_clip_preserve(cr);
    set_colour(cr, st.fill);
    cairo_fill(cr);
    if (st.hatched) hatch(cr, a.x0, a.y0, a.x1, a.y1, 7 * u, 1.1 * u, {0.45, 0.45, 0.47});
    cairo_restore(cr);
}

// A label's box, px, to keep labels apart.
struct Box {
    double x0, y0, x1, y1;
    bool overlaps(const Box& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
};

// The point `fraction` of the way along a polyline (in device units).
Vec2 along(const std::vector<Vec2>& pts, double fraction) {
    double total = 0;
    for (std::size_t k = 1; k < pts.size(); ++k) total += std::hypot(pts[k].x() - pts[k - 1].x(), pts[k].y() - pts[k - 1].y());
    double left = fraction * total;
    for (std::size_t k = 1; k < pts.size(); ++k) {
        const double d = std::hypot(pts[k].x() - pts[k - 1].x(), pts[k].y() - pts[k - 1].y());
        if (d >= left && d > 0) return pts[k - 1] + (pts[k] - pts[k - 1]) * left / d;
        left -= d;
    }
    return pts.back();
}

// Contour lines, each labelled with its value where the label clears the others (and `taken`).
void draw_contours(cairo_t* cr, const Theme& th, const Sorted& s, const std::vector<double>& levels, int decimals,
                   const PlotArea& a, double u, double body, std::vector<Box> taken) {
    const auto T = [&](double n) { return text_size(n, u, body); };
    const Rgba line{th.text.r, th.text.g, th.text.b, 0.75};
    struct Pending {
        Vec2 at = Vec2::Zero();
        std::string text;
    };
    std::vector<Pending> labels;
    for (std::size_t n = 0; n < levels.size(); ++n) {
        for (const std::vector<Vec2>& l : contour_lines(s.xs, s.ys, s.z, levels[n])) {
            std::vector<Vec2> px;
            double length = 0;
            for (const Vec2& q : l) {
                px.push_back({a.px(q.x()), a.py(q.y())});
                if (px.size() > 1) length += std::hypot(px.back().x() - px[px.size() - 2].x(), px.back().y() - px[px.size() - 2].y());
            }
            set_colour(cr, line);
            cairo_set_line_width(cr, 1.1 * u);
            cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
            for (std::size_t k = 0; k < px.size(); ++k) (k ? cairo_line_to : cairo_move_to)(cr, px[k].x(), px[k].y());
            cairo_stroke(cr);
            if (length < 90 * u) continue;  // too short to carry its value
            // Neighbouring levels try different places first, so parallel lines' labels step apart.
            const std::string text = format_tick(levels[n], decimals);
            const double w = text_width(cr, th.font, T(11), text) + 6 * u, h = 15 * u;
            for (double f : {0.5, 0.3, 0.7, 0.15, 0.85, 0.4, 0.6}) {
                const double shifted = n % 2 ? 1.0 - f : f;
                const Vec2 at = along(px, shifted);
                const Box box{at.x() - 0.5 * w, at.y() - 0.5 * h, at.x() + 0.5 * w, at.y() + 0.5 * h};
                if (box.x0 < a.x0 || box.x1 > a.x1 || box.y0 < a.y0 || box.y1 > a.y1) continue;
                if (std::any_of(taken.begin(), taken.end(), [&](const Box& b) { return b.overlaps(box); })) continue;
                taken.push_back(box);
                labels.push_back({at, text});
                break;
            }
        }
    }
    for (const Pending& p : labels)
        halo_text(cr, th.font, T(11), p.at.x(), p.at.y() + 4 * u, p.text, th.text, th.background, 3 * u, 0.5);
}

// Where the contest's dragon is marked, and the box its label takes (none if it is not shown).
struct Mark {
    double x, y;
    bool left;  // the label to the left of the mark (where it would leave the frame on the right)
    Box box;
    double text_x = 0, text_y = 0;  // the label's start and baseline
};
std::optional<Mark> place_mark(cairo_t* cr, const SweepMap& map, const PlotArea& a, double u) {
    const auto T = [&](double n) { return text_size(n, u, map.text_px); };
    if (!map.x.mark || !map.y->mark) return std::nullopt;
    const double mx = a.px(*map.x.mark), my = a.py(*map.y->mark);
    if (mx < a.x0 || mx > a.x1 || my < a.y0 || my > a.y1) return std::nullopt;
    const double tw = text_width(cr, map.theme.font, T(13), map.mark_label);
    const bool left = mx + 12 * u + tw > a.x1;
    if (!left || mx - 12 * u - tw >= a.x0) {
        const double x0 = left ? mx - 16 * u - tw : mx - 9 * u, x1 = left ? mx + 9 * u : mx + 16 * u + tw;
        return Mark{mx, my, left, {x0, my - 10 * u, x1, my + 10 * u}, left ? mx - 12 * u - tw : mx + 12 * u, my + 4.5 * u};
    }
    // Room on neither side (a narrow map at a print size): under the mark, or over it near the
    // bottom, centred on it as far as the frame allows.
    const double size = T(13);
    const double tx = std::max(a.x0 + 3 * u, std::min(mx - 0.5 * tw, a.x1 - 3 * u - tw));
    const bool below = my + 9 * u + 1.2 * size <= a.y1;
    const double ty = below ? my + 9 * u + 0.8 * size : my - 9 * u - 0.25 * size;
    const double top = ty - 0.8 * size, bottom = ty + 0.25 * size;
    return Mark{mx, my, false, {std::min(tx, mx - 9 * u), std::min(top, my - 10 * u), std::max(tx + tw, mx + 9 * u),
                                std::max(bottom, my + 10 * u)}, tx, ty};
}

void draw_mark(cairo_t* cr, const SweepMap& map, const Mark& m, double u) {
    const auto T = [&](double n) { return text_size(n, u, map.text_px); };
    cairo_new_sub_path(cr);
    cairo_arc(cr, m.x, m.y, 6.5 * u, 0, 2 * std::numbers::pi);
    set_colour(cr, {1, 1, 1, 0.9});
    cairo_fill_preserve(cr);
    set_colour(cr, {0.1, 0.1, 0.12});
    cairo_set_line_width(cr, 2.2 * u);
    cairo_stroke(cr);
    cairo_arc(cr, m.x, m.y, 2.2 * u, 0, 2 * std::numbers::pi);
    cairo_fill(cr);
    halo_text(cr, map.theme.font, T(13), m.text_x, m.text_y, map.mark_label, {0.05, 0.05, 0.07}, {1, 1, 1}, 3.5 * u, 0.0);
}

}  // namespace

void draw_heat_panel(cairo_t* cr, const SweepMap& map, const MapPanel& panel, double x, double y, double w, double h) {
    const Theme& th = map.theme;
    Plot p;
    p.text_px = map.text_px;
    const double u = plot_unit(p, w, h);
    const auto T = [&](double n) { return text_size(n, u, map.text_px); };
    const Sorted s = sort_panel(map, panel);
    const Ticks ticks = nice_ticks(s.lo, s.hi, 6);
    // Contour lines at the colour bar's ticks inside the range (more if there are too few).
    std::vector<double> levels;
    for (double v : ticks.values)
        if (v > s.lo && v < s.hi) levels.push_back(v);
    Ticks fine = ticks;
    if (levels.size() < 3) {
        fine = nice_ticks(s.lo, s.hi, 10);
        levels.clear();
        for (double v : fine.values)
            if (v > s.lo && v < s.hi) levels.push_back(v);
    }
    if (!s.any) levels.clear();
    const std::vector<double> ex = edges(s.xs), ey = edges(s.ys);

    p.theme = th;
    p.title = fmt::format(fmt::runtime(words(map.language).map_over),
                          map.language == Language::en ? capitalised(panel.quantity) : panel.quantity, map.x.quantity,
                          map.y->quantity);
    p.note = map.note;
    if (map.text_px > 0) p.title.clear(), p.note.clear();  // at a print size: the paper's caption says it
    p.x_label = axis_label(map.x.quantity, map.x.unit);
    p.y_label = axis_label(map.y->quantity, map.y->unit);
    p.x_min = ex.front(), p.x_max = ex.back(), p.y_min = ey.front(), p.y_max = ey.back();
    p.legend = Plot::Legend::none;
    p.underlay = [&](cairo_t* c, const PlotArea& a, double) {
        const std::size_t ny = s.ys.size();
        for (std::size_t k = 0; k < s.cells.size(); ++k) {
            if (s.cells[k] != MapCell::value || std::isnan(s.z[k])) continue;
            const std::size_t i = k / ny, j = k % ny;
            set_colour(c, ramp_colour(th.speed_ramp, (s.z[k] - s.lo) / (s.hi - s.lo)));
            // A pixel wider and taller than the cell, under its neighbours: no seams between cells.
            const double x0 = a.px(ex[i]), x1 = a.px(ex[i + 1]), y0 = a.py(ey[j + 1]), y1 = a.py(ey[j]);
            cairo_rectangle(c, x0 - 0.5, y0 - 0.5, x1 - x0 + 1.0, y1 - y0 + 1.0);
            cairo_fill(c);
        }
        for (MapCell kind : other_cell_kinds()) draw_other_cells(c, th, panel, s, kind, ex, ey, a, u);
        const std::optional<Mark> mark = place_mark(c, map, a, u);
        draw_contours(c, th, s, levels, fine.decimals, a, u, map.text_px, mark ? std::vector<Box>{mark->box} : std::vector<Box>{});
        if (mark) draw_mark(c, map, *mark, u);
    };
    // Room on the right for the colour bar, and under the plot for the legend of other cells.
    double widest = 0;
    for (double v : ticks.values) widest = std::max(widest, text_width(cr, th.font, T(12), format_tick(v, ticks.decimals)));
    const double bar_room = 16 * u + 7 * u + widest + 30 * u;
    // The legend under the frame, across the panel.
    const double legend_x = x + 18 * u, legend_w = w - 36 * u;
    const double legend_room = cell_legend_height(cr, th, panel, legend_w, u, map.text_px, map.language);
    const PlotArea a = draw_plot(cr, p, x, y, w - bar_room, h - legend_room);
    if (s.any) draw_colour_bar(cr, th, panel, s, ticks, levels, a, x + w - bar_room, u, map.text_px);
    if (legend_room > 0) draw_cell_legend(cr, th, panel, legend_x, y + h - legend_room, legend_w, u, map.text_px, map.language);
}

}  // namespace dragon::render
