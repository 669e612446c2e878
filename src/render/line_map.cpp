// A line plot panel: one measure against one varied value, the scenarios without a value marked
// as what they are in a strip under the values (outside their axis, sharing the x axis), and the
// contest's dragon as a reference line where the map holds it.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "dragon/plot.hpp"
#include "map_panels.hpp"
#include "render/words.hpp"

namespace dragon::render {

void draw_line_panel(cairo_t* cr, const SweepMap& map, const MapPanel& panel, double x, double y, double w, double h) {
    const Theme& th = map.theme;
    const std::vector<std::size_t> order = sorted_order(map.x.values);
    Plot p;
    p.theme = th;
    std::string title = fmt::format(fmt::runtime(words(map.language).map_against), panel.quantity, map.x.quantity);
    if (!title.empty() && title[0] >= 'a' && title[0] <= 'z') title[0] = static_cast<char>(title[0] - 'a' + 'A');
    p.title = title;
    p.note = map.note;
    if (map.text_px > 0) p.title.clear(), p.note.clear();  // at a print size: the paper's caption says it
    p.x_label = axis_label(map.x.quantity, map.x.unit);
    p.y_label = axis_label(panel.quantity, panel.unit);
    // The line needs no legend (the axis names it); the markers' legend goes under the plot.
    p.legend = Plot::Legend::none;
    PlotSeries values{panel.quantity, {}, series_colour(th, 0), 1.8, true, false, true, 3.0};
    // A refused value (a pitch of -1) sets no axis: the x axis spans the scenarios that ran, and
    // a refused one outside them is marked at the strip's edge on its side.
    double x_lo = INFINITY, x_hi = -INFINITY;
    for (std::size_t i : order)
        if (panel.cells[i] != MapCell::refused) x_lo = std::min(x_lo, map.x.values[i]), x_hi = std::max(x_hi, map.x.values[i]);
    const auto outside = [&](std::size_t i) { return x_hi >= x_lo && (map.x.values[i] < x_lo || map.x.values[i] > x_hi); };
    double lo = INFINITY, hi = -INFINITY;
    for (std::size_t i : order) {
        if (outside(i)) continue;
        const bool ok = panel.cells[i] == MapCell::value && std::isfinite(panel.values[i]);
        values.points.push_back({map.x.values[i], ok ? panel.values[i] : NAN});  // NaN: the line breaks
        if (ok) lo = std::min(lo, panel.values[i]), hi = std::max(hi, panel.values[i]);
    }
    if (!(hi >= lo)) lo = 0.0, hi = 1.0;
    if (hi - lo < 1e-12 * std::max(1.0, std::abs(lo))) lo -= 0.5, hi += 0.5;
    p.series.push_back(values);
    // Scenarios without a value: a marker each in the strip under the frame, never on the
    // value axis (a dot at "195 s" would read as a first contact then).
    const bool others = has_other_cells(panel);
    if (others) {
        p.strip_px = 24;
        p.strip_label = words(map.language).no_value;
        p.strip = [&](cairo_t* c, const PlotArea& band, double su) {
            for (std::size_t i : order) {
                if (panel.cells[i] == MapCell::value) continue;
                const CellStyle st = cell_style(th, panel.cells[i], panel, map.language);
                const double r = 4.5 * su;
                const double mx = std::clamp(band.px(map.x.values[i]), band.x0 + 1.5 * r, band.x1 - 1.5 * r);
                draw_cell_marker(c, panel.cells[i], st, mx, 0.5 * (band.y0 + band.y1), r);
            }
        };
    }
    p.y_min = lo - 0.05 * (hi - lo);
    p.y_max = hi + 0.08 * (hi - lo);
    if (map.x.mark) p.ref_lines.push_back({true, *map.x.mark, map.mark_label, th.text, true});
    p.text_px = map.text_px;
    const double u = plot_unit(p, w, h);  // the plot's own unit
    const double legend_x = x + 18 * u, legend_w = w - 36 * u;
    const double legend_room = cell_legend_height(cr, th, panel, legend_w, u, map.text_px, map.language);
    draw_plot(cr, p, x, y, w, h - legend_room);
    if (legend_room > 0) draw_cell_legend(cr, th, panel, legend_x, y + h - legend_room, legend_w, u, map.text_px, map.language, true);
}

}  // namespace dragon::render
