// The plot module: layout (margins from the text sizes), axes, ticks, series, legend.
#include "dragon/plot.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <optional>
#include <cstring>
#include <limits>
#include <numbers>

#include <fmt/format.h>

#include "dragon/atomic_file.hpp"
#include "render/cairo_handles.hpp"
#include "dragon/scenario.hpp"
#include "render/paint.hpp"

namespace dragon {

using render::set_colour;

Rgba series_colour(const Theme& theme, int i) {
    // Okabe-Ito: distinguishable with every common colour-vision deficiency.
    static const Rgba light[] = {{0.00, 0.45, 0.70}, {0.84, 0.37, 0.00}, {0.00, 0.62, 0.45},
                                 {0.80, 0.47, 0.65}, {0.90, 0.62, 0.00}, {0.34, 0.71, 0.91},
                                 {0.35, 0.35, 0.35}, {0.60, 0.15, 0.15}};
    static const Rgba dark[] = {{0.34, 0.71, 0.91}, {0.90, 0.62, 0.00}, {0.00, 0.75, 0.55},
                                {0.90, 0.60, 0.78}, {0.94, 0.89, 0.26}, {0.60, 0.80, 1.00},
                                {0.80, 0.80, 0.80}, {1.00, 0.45, 0.40}};
    const bool is_dark = theme.background.r + theme.background.g + theme.background.b < 1.5;
    const int n = static_cast<int>(std::size(light));
    const int k = ((i % n) + n) % n;
    return is_dark ? dark[k] : light[k];
}

namespace {

struct Range {
    double lo = std::numeric_limits<double>::infinity();
    double hi = -std::numeric_limits<double>::infinity();
    void add(double v) {
        if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
    }
    bool empty() const { return !(hi >= lo); }
};

// Data box: the given limits, else the data's range padded by 4 % (a flat series gets +-1).
void data_ranges(const Plot& p, Range& xr, Range& yr) {
    for (const auto& s : p.series)
        for (Vec2 q : s.points) xr.add(q.x()), yr.add(q.y());
    for (const auto& l : p.labels) xr.add(l.at.x()), yr.add(l.at.y());
    for (const auto& r : p.ref_lines) (r.vertical ? xr : yr).add(r.value);
    auto finish = [](Range& r, std::optional<double> lo, std::optional<double> hi) {
        if (r.empty()) r = {0, 1};
        if (r.hi - r.lo < 1e-12 * std::max(1.0, std::abs(r.lo))) r.lo -= 1, r.hi += 1;
        const double pad = 0.04 * (r.hi - r.lo);
        r.lo = lo.value_or(r.lo - pad);
        r.hi = hi.value_or(r.hi + pad);
    };
    finish(xr, p.x_min, p.x_max);
    finish(yr, p.y_min, p.y_max);
}

struct Frame2 {
    double x0, y0, x1, y1;  // plot area in device units (y0 top)
    Range xr, yr;
    double px(double x) const { return x0 + (x - xr.lo) / (xr.hi - xr.lo) * (x1 - x0); }
    double py(double y) const { return y1 - (y - yr.lo) / (yr.hi - yr.lo) * (y1 - y0); }
};

// Widen one axis's range so a data unit has the same length in x and y.
void equalise(Frame2& f) {
    const double sx = (f.x1 - f.x0) / (f.xr.hi - f.xr.lo), sy = (f.y1 - f.y0) / (f.yr.hi - f.yr.lo);
    if (sx > sy) {
        const double half = 0.5 * (f.x1 - f.x0) / sy, mid = 0.5 * (f.xr.lo + f.xr.hi);
        f.xr = {mid - half, mid + half};
    } else {
        const double half = 0.5 * (f.y1 - f.y0) / sx, mid = 0.5 * (f.yr.lo + f.yr.hi);
        f.yr = {mid - half, mid + half};
    }
}

void set_dash(cairo_t* cr, bool dashed, double u) {
    if (!dashed) return cairo_set_dash(cr, nullptr, 0, 0);
    const double d[2] = {6 * u, 4 * u};
    cairo_set_dash(cr, d, 2, 0);
}

void draw_series(cairo_t* cr, const Frame2& f, const PlotSeries& s, double u) {
    set_colour(cr, s.colour);
    if (render::layout_recording() && !s.label.empty())  // the points a legend entry explains
        for (Vec2 q : s.points)
            if (std::isfinite(q.x()) && std::isfinite(q.y()))
                render::log_placed(cr, render::LayoutItem::Kind::mark, f.px(q.x()), f.py(q.y()), f.px(q.x()), f.py(q.y()),
                                   s.label);
    if (s.line && s.points.size() > 1) {
        bool pen = false;
        for (Vec2 q : s.points) {
            if (!std::isfinite(q.x()) || !std::isfinite(q.y())) {
                pen = false;
                continue;
            }
            if (pen) cairo_line_to(cr, f.px(q.x()), f.py(q.y()));
            else cairo_move_to(cr, f.px(q.x()), f.py(q.y()));
            pen = true;
        }
        cairo_set_line_width(cr, s.width_px * u);
        cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
        set_dash(cr, s.dashed, u);
        cairo_stroke(cr);
        set_dash(cr, false, u);
    }
    if (s.markers) {
        for (Vec2 q : s.points) {
            if (!std::isfinite(q.y())) continue;
            cairo_new_sub_path(cr);
            cairo_arc(cr, f.px(q.x()), f.py(q.y()), s.marker_px * u, 0, 2 * std::numbers::pi);
        }
        cairo_fill(cr);
    }
}

std::vector<const PlotSeries*> legend_entries(const Plot& p) {
    std::vector<const PlotSeries*> entries;
    if (p.legend == Plot::Legend::none) return entries;
    for (const auto& s : p.series)
        if (!s.label.empty()) entries.push_back(&s);
    return entries;
}

void draw_sample(cairo_t* cr, const PlotSeries& s, double x, double y, double sample, double u) {
    set_colour(cr, s.colour);
    if (s.line) {
        cairo_move_to(cr, x, y);
        cairo_line_to(cr, x + sample, y);
        cairo_set_line_width(cr, s.width_px * u);
        set_dash(cr, s.dashed, u);
        cairo_stroke(cr);
        set_dash(cr, false, u);
    }
    if (s.markers) {
        cairo_arc(cr, x + 0.5 * sample, y, s.marker_px * u, 0, 2 * std::numbers::pi);
        cairo_fill(cr);
    }
}

// At a print size the legend goes above the frame, its entries in rows across the frame's
// width: inside, at a column's width, it would cover the data. Where each entry goes, as
// offsets from the legend's top left, and the legend's height.
struct LegendRows {
    std::vector<Vec2> at;
    double height = 0;
};
LegendRows legend_rows(cairo_t* cr, const Plot& p, double width, double u) {
    LegendRows out;
    const std::vector<const PlotSeries*> entries = legend_entries(p);
    if (entries.empty()) return out;
    const double size = render::text_size(12, u, p.text_px), row = 1.45 * size, sample = 20 * u, gap = 14 * u;
    double x = 0, y = 0;
    for (const PlotSeries* s : entries) {
        const double w = sample + 5 * u + render::text_width(cr, p.theme.font, size, s->label);
        if (x > 0 && x + w > width) x = 0, y += row;
        out.at.push_back({x, y});
        x += w + gap;
    }
    out.height = y + row;
    return out;
}

void draw_legend_rows(cairo_t* cr, const Plot& p, const LegendRows& rows, double x0, double y0, double u) {
    const std::vector<const PlotSeries*> entries = legend_entries(p);
    const double size = render::text_size(12, u, p.text_px), row = 1.45 * size, sample = 20 * u;
    for (std::size_t i = 0; i < entries.size(); ++i) {
        const double x = x0 + rows.at[i].x(), y = y0 + rows.at[i].y() + 0.5 * row;
        draw_sample(cr, *entries[i], x, y, sample, u);
        set_colour(cr, p.theme.text);
        render::text(cr, p.theme.font, size, x + sample + 5 * u, y, entries[i]->label, 0.0, 0.5);
    }
}

// The in-frame legend's size, px.
Vec2 legend_size(cairo_t* cr, const Plot& p, double u) {
    const std::vector<const PlotSeries*> entries = legend_entries(p);
    const double size = render::text_size(12, u, p.text_px), row = 18 * u, sample = 24 * u, pad = 8 * u;
    double tw = 0;
    for (auto* s : entries) tw = std::max(tw, render::text_width(cr, p.theme.font, size, s->label));
    return {pad + sample + 6 * u + tw + pad, pad + row * static_cast<double>(entries.size()) + 2 * u};
}

// The corner for the in-frame legend: the one asked for, or the first other (round the frame)
// where it covers none of the points it explains; none when it would cover some in every one
// (it then goes above the frame, as at a print size).
std::optional<Vec2> legend_corner(cairo_t* cr, const Plot& p, const Frame2& f, double u) {
    const std::vector<const PlotSeries*> entries = legend_entries(p);
    const Vec2 size = legend_size(cr, p, u);
    const double bw = size.x(), bh = size.y();
    const bool left0 = p.legend == Plot::Legend::top_left || p.legend == Plot::Legend::bottom_left;
    const bool top0 = p.legend == Plot::Legend::top_left || p.legend == Plot::Legend::top_right;
    for (const auto& [left, top] : {std::pair{left0, top0}, std::pair{!left0, top0}, std::pair{left0, !top0},
                                   std::pair{!left0, !top0}}) {
        const double x = left ? f.x0 + 10 * u : f.x1 - 10 * u - bw, y = top ? f.y0 + 10 * u : f.y1 - 10 * u - bh;
        bool clear = true;
        for (const PlotSeries* s : entries)
            for (Vec2 q : s->points)
                if (clear && std::isfinite(q.x()) && std::isfinite(q.y())) {
                    const double qx = f.px(q.x()), qy = f.py(q.y());
                    clear = !(qx >= x - 2 * u && qx <= x + bw + 2 * u && qy >= y - 2 * u && qy <= y + bh + 2 * u);
                }
        if (clear) return Vec2{x, y};
    }
    return std::nullopt;
}

void draw_legend(cairo_t* cr, const Plot& p, const Frame2& f, double u) {
    const std::vector<const PlotSeries*> entries = legend_entries(p);
    if (entries.empty() || p.text_px > 0) return;  // at a print size: legend_rows, above the frame
    const std::optional<Vec2> corner = legend_corner(cr, p, f, u);
    if (!corner) return;  // above the frame
    const double size = render::text_size(12, u, p.text_px), row = 18 * u, sample = 24 * u, pad = 8 * u;
    const Vec2 box = legend_size(cr, p, u);
    const double bw = box.x(), bh = box.y(), bx = corner->x(), by = corner->y();
    Rgba bg = p.theme.background;
    bg.a = 0.88;
    set_colour(cr, bg);
    cairo_rectangle(cr, bx, by, bw, bh);
    render::log_placed(cr, render::LayoutItem::Kind::legend, bx, by, bx + bw, by + bh, "legend");
    cairo_fill_preserve(cr);
    set_colour(cr, p.theme.grid);
    cairo_set_line_width(cr, 1 * u);
    cairo_stroke(cr);
    for (std::size_t i = 0; i < entries.size(); ++i) {
        const PlotSeries& s = *entries[i];
        const double y = by + pad + row * (i + 0.5);
        draw_sample(cr, s, bx + pad, y, sample, u);
        set_colour(cr, p.theme.text);
        render::text(cr, p.theme.font, size, bx + pad + sample + 6 * u, y, s.label, 0.0, 0.5);
    }
}

}  // namespace

double plot_unit(const Plot& p, double w, double h) {
    if (p.text_px > 0) return p.text_px / 12.0;
    return std::max(0.4, std::min(w / 900.0, h / 560.0) * 1.25);
}

PlotArea draw_plot(cairo_t* cr, const Plot& p, double x, double y, double w, double h) {
    const double u = plot_unit(p, w, h);
    const auto T = [&](double nominal) { return render::text_size(nominal, u, p.text_px); };
    const Theme& th = p.theme;
    cairo_save(cr);
    cairo_rectangle(cr, x, y, w, h);
    cairo_clip(cr);
    set_colour(cr, {th.background.r, th.background.g, th.background.b, 1});
    cairo_paint(cr);

    Range xr, yr;
    data_ranges(p, xr, yr);
    const auto yt0 = render::nice_ticks(yr.lo, yr.hi, 6);
    double ytw = 0;
    for (double v : yt0.values)
        ytw = std::max(ytw, render::text_width(cr, th.font, T(12), render::format_tick(v, yt0.decimals)));
    const bool banded = p.strip_px > 0 && p.strip;
    if (banded) ytw = std::max(ytw, render::text_width(cr, th.font, T(11), p.strip_label));
    const double band_gap = 6 * u, band_h = banded ? p.strip_px * u : 0.0;
    // Title and note run across the frame's width, wrapped or set smaller rather than clipped;
    // the frame starts below however many lines they take.
    // The value axis's name runs up the left side; at a print size, where it may not shorten, it
    // wraps onto a second line when the side is too short for it (the frame moves right by it).
    const render::FittedText y_name =
        render::fit_text(cr, th.font, T(13), p.y_label,
                         std::max(h - (70 + (p.title.empty() ? 0 : 40) + (p.note.empty() ? 0 : 30)) * u -
                                      (banded ? p.strip_px * u + 6 * u : 0.0) - (p.text_px > 0 ? 2.5 * T(12) : 0.0),
                                  0.3 * h),
                         false, 2, p.text_px > 0);
    const double y_extra = y_name.lines.size() > 1 ? 1.25 * y_name.size * static_cast<double>(y_name.lines.size() - 1) : 0.0;
    const double x0 = x + ytw + (p.y_label.empty() ? 18 : 40) * u + y_extra, x1 = x + w - 20 * u;
    const bool keep = p.text_px > 0;  // at a print size, text wraps rather than shrinks
    const render::FittedText title = render::fit_text(cr, th.font, T(15), p.title, x1 - x0, true, 2, keep);
    const render::FittedText note = render::fit_text(cr, th.font, T(12), p.note, x1 - x0, false, 2, keep);
    std::vector<double> title_y, note_y;  // baselines
    double line_y = y + 24 * u;
    for (std::size_t i = 0; i < title.lines.size(); ++i, line_y += 1.3 * title.size) title_y.push_back(line_y);
    if (!title.lines.empty()) line_y += 20 * u - 1.3 * title.size;
    for (std::size_t i = 0; i < note.lines.size(); ++i, line_y += 1.35 * note.size) note_y.push_back(line_y);
    double top = title_y.empty() && note_y.empty() ? y + 16 * u
                 : note_y.empty()                  ? title_y.back() + 16 * u
                                                   : note_y.back() + 14 * u;
    LegendRows rows = p.text_px > 0 ? legend_rows(cr, p, x1 - x0, u) : LegendRows{};
    const double legend_y = top - (title_y.empty() && note_y.empty() ? 10 * u : 4 * u);
    const auto frame = [&] {
        Frame2 out{x0, rows.height > 0 ? legend_y + rows.height + 6 * u : top, x1,
                   y + h - (p.x_label.empty() ? 30 : 52) * u - (banded ? band_gap + band_h : 0.0), xr, yr};
        if (p.equal_aspect) equalise(out);
        return out;
    };
    Frame2 f = frame();
    // On screen, a legend that would cover its data in every corner goes above the frame.
    if (rows.height == 0 && !legend_entries(p).empty() && !legend_corner(cr, p, f, u)) {
        rows = legend_rows(cr, p, x1 - x0, u);
        f = frame();
    }
    const auto xt = render::nice_ticks(f.xr.lo, f.xr.hi, std::max(3, static_cast<int>((f.x1 - f.x0) / (90 * u))));
    const auto yt = render::nice_ticks(f.yr.lo, f.yr.hi, std::max(3, static_cast<int>((f.y1 - f.y0) / (60 * u))));

    // Grid, then data clipped to the plot area, then the frame and ticks on top.
    // The band under the data area, when there is one: where the x axis's ticks go.
    const double band_y0 = f.y1 + band_gap, axis_y = banded ? band_y0 + band_h : f.y1;
    cairo_set_line_width(cr, 1 * u);
    set_colour(cr, th.grid);
    for (double v : xt.values) cairo_move_to(cr, f.px(v), f.y0), cairo_line_to(cr, f.px(v), f.y1);
    if (banded)
        for (double v : xt.values) cairo_move_to(cr, f.px(v), band_y0), cairo_line_to(cr, f.px(v), axis_y);
    for (double v : yt.values) cairo_move_to(cr, f.x0, f.py(v)), cairo_line_to(cr, f.x1, f.py(v));
    cairo_stroke(cr);

    const PlotArea area{f.x0, f.y0, f.x1, f.y1, f.xr.lo, f.xr.hi, f.yr.lo, f.yr.hi};
    cairo_save(cr);
    cairo_rectangle(cr, f.x0, f.y0, f.x1 - f.x0, f.y1 - f.y0);
    cairo_clip(cr);
    if (p.underlay) {
        cairo_save(cr);
        p.underlay(cr, area, u);
        cairo_restore(cr);
    }
    for (const auto& r : p.ref_lines) {
        set_colour(cr, r.colour);
        cairo_set_line_width(cr, 1.3 * u);
        set_dash(cr, r.dashed, u);
        if (r.vertical) cairo_move_to(cr, f.px(r.value), f.y0), cairo_line_to(cr, f.px(r.value), f.y1);
        else cairo_move_to(cr, f.x0, f.py(r.value)), cairo_line_to(cr, f.x1, f.py(r.value));
        cairo_stroke(cr);
        set_dash(cr, false, u);
        if (!r.label.empty()) {
            if (r.vertical) {
                // Right of the line, or left of it when it would run past the frame.
                // Either way it stays inside the frame (a line near an edge: over the line).
                const double lw = render::text_width(cr, th.font, T(11), r.label);
                const bool left = f.px(r.value) + 4 * u + lw > f.x1;
                const double start = left ? f.px(r.value) - 4 * u - lw : f.px(r.value) + 4 * u;
                render::text(cr, th.font, T(11), std::max(f.x0 + 3 * u, std::min(start, f.x1 - 3 * u - lw)),
                             f.y0 + 14 * u, r.label);
            }
            else
                render::text(cr, th.font, T(11), f.x1 - 6 * u, f.py(r.value) - 5 * u, r.label, 1.0);
        }
    }
    for (const auto& s : p.series) draw_series(cr, f, s, u);
    for (const auto& l : p.labels) {
        const double lx = f.px(l.at.x()), ly = f.py(l.at.y());
        set_colour(cr, l.colour);
        if (l.dot) {
            cairo_arc(cr, lx, ly, 3.2 * u, 0, 2 * std::numbers::pi);
            cairo_fill(cr);
        }
        // Kept inside the frame: a label that would run past an edge moves in along its line.
        const double size = T(l.size_px), tw = render::text_width(cr, th.font, size, l.text);
        double left = lx + l.dx_px * u - l.align * tw;
        left = std::max(f.x0 + 3 * u, std::min(left, f.x1 - 3 * u - tw));
        const double base = std::max(f.y0 + 0.8 * size + 2 * u, std::min(ly + l.dy_px * u, f.y1 - 0.25 * size - 2 * u));
        render::halo_text(cr, th.font, size, left, base, l.text, l.colour, th.background, 3.0 * u, 0.0);
    }
    cairo_restore(cr);

    if (banded) {
        const PlotArea band{f.x0, band_y0, f.x1, axis_y, f.xr.lo, f.xr.hi, 0.0, 1.0};
        cairo_save(cr);
        cairo_rectangle(cr, f.x0, band_y0, f.x1 - f.x0, band_h);
        cairo_clip(cr);
        p.strip(cr, band, u);
        cairo_restore(cr);
    }

    set_colour(cr, th.text);
    cairo_set_line_width(cr, 1.2 * u);
    cairo_rectangle(cr, f.x0, f.y0, f.x1 - f.x0, f.y1 - f.y0);
    cairo_stroke(cr);
    const double tick = 5 * u, size = T(12);
    if (banded) {
        cairo_rectangle(cr, f.x0, band_y0, f.x1 - f.x0, band_h);
        cairo_stroke(cr);
        render::text(cr, th.font, T(11), f.x0 - tick - 4 * u, band_y0 + 0.5 * band_h, p.strip_label, 1.0, 0.5);
    }
    for (double v : xt.values) {
        cairo_move_to(cr, f.px(v), axis_y);
        cairo_line_to(cr, f.px(v), axis_y + tick);
        cairo_stroke(cr);
        render::text(cr, th.font, size, f.px(v), axis_y + tick + 4 * u + 0.73 * size,
                     render::format_tick(v, xt.decimals), 0.5);
    }
    for (double v : yt.values) {
        cairo_move_to(cr, f.x0 - tick, f.py(v));
        cairo_line_to(cr, f.x0, f.py(v));
        cairo_stroke(cr);
        render::text(cr, th.font, size, f.x0 - tick - 4 * u, f.py(v), render::format_tick(v, yt.decimals), 1.0, 0.5);
    }
    if (!p.x_label.empty())
        render::text(cr, th.font, T(13), 0.5 * (f.x0 + f.x1), y + h - 12 * u, p.x_label, 0.5);
    if (!p.y_label.empty()) {
        cairo_save(cr);
        cairo_translate(cr, x + 18 * u, 0.5 * (f.y0 + f.y1));
        cairo_rotate(cr, -std::numbers::pi / 2);
        for (std::size_t i = 0; i < y_name.lines.size(); ++i)
            render::text(cr, th.font, y_name.size, 0, 1.25 * y_name.size * static_cast<double>(i), y_name.lines[i], 0.5);
        cairo_restore(cr);
    }
    for (std::size_t i = 0; i < title.lines.size(); ++i)
        render::text(cr, th.font, title.size, x0, title_y[i], title.lines[i], 0.0, 0.0, true);
    Rgba soft = th.text;
    soft.a = 0.75;
    set_colour(cr, soft);
    for (std::size_t i = 0; i < note.lines.size(); ++i) render::text(cr, th.font, note.size, x0, note_y[i], note.lines[i]);
    if (rows.height > 0) draw_legend_rows(cr, p, rows, x0, legend_y, u);
    else draw_legend(cr, p, f, u);
    cairo_restore(cr);
    return area;
}

void render_plot_png(const Plot& plot, int w, int h, const std::string& path, RunOutputs* outputs) {
    if (w < 100 || h < 100 || w > 16384 || h > 16384)
        throw InputError(fmt::format("plot size {} x {} px is not allowed: each side must be 100..16384", w, h));
    AtomicFile out(path, outputs);
    cairo::Surface surface(cairo_image_surface_create(CAIRO_FORMAT_RGB24, w, h));
    {
        cairo::Context cr = cairo::make_context(surface.get());
        draw_plot(cr.get(), plot, 0, 0, w, h);
        if (cairo_status(cr.get()) != CAIRO_STATUS_SUCCESS)
            throw SolverError(std::string("drawing the plot: ") + cairo_status_to_string(cairo_status(cr.get())));
    }
    errno = 0;
    if (const cairo_status_t st = cairo_surface_write_to_png(surface.get(), out.temp_path().c_str()))
        throw out.write_error(errno != 0 ? std::strerror(errno) : cairo_status_to_string(st));
    out.commit();
}

}  // namespace dragon
