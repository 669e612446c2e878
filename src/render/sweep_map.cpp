// A sweep's map: its panels one under the other, the styles of cells without a value, and the
// output files.
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <numbers>
#include <numeric>

#include <fmt/format.h>

#include "dragon/atomic_file.hpp"
#include "render/cairo_handles.hpp"
#include "dragon/scenario.hpp"
#include "map_panels.hpp"
#include "render/paint.hpp"
#include "render/png8.hpp"
#include "render/words.hpp"
#include "render/vector_out.hpp"

namespace dragon {

using namespace render;

std::string axis_label(const std::string& quantity, const std::string& unit) {
    return unit.empty() ? quantity : fmt::format("{} ({})", quantity, unit);
}

namespace render {

CellStyle cell_style(const Theme& theme, MapCell cell, const MapPanel& panel, Language language) {
    const Words& w = words(language);
    // Pale fills, away from the value ramp's colours, for the kinds that are not values; the
    // answer outside the range searched is blue below it and rose above it; a chain that
    // collides from the start a deep red, as strong as the verdict.
    switch (cell) {
        case MapCell::jam: return {{0.88, 0.88, 0.89}, true, panel.jam_label, {0.84, 0.37, 0.00}};
        case MapCell::refused: return {{0.60, 0.60, 0.63}, false, w.cell_refused, {0.40, 0.40, 0.43}};
        case MapCell::no_value: return {{0.92, 0.89, 0.78}, false, w.cell_none, {0.62, 0.52, 0.25}};
        case MapCell::below_range: return {{0.76, 0.84, 0.95}, false, panel.below_label, {0.20, 0.42, 0.80}};
        case MapCell::above_range: return {{0.97, 0.80, 0.78}, false, panel.above_label, {0.82, 0.30, 0.25}};
        case MapCell::overlapping:
            return {{0.55, 0.11, 0.13}, false, w.cell_overlapping, {0.55, 0.11, 0.13}};
        case MapCell::missing: return {theme.background, false, w.cell_missing, {0.6, 0.6, 0.6}};
        case MapCell::value: break;
    }
    return {theme.background, false, "", theme.text};
}

const std::vector<MapCell>& other_cell_kinds() {
    static const std::vector<MapCell> kinds = {MapCell::jam,         MapCell::refused,     MapCell::overlapping,
                                               MapCell::below_range, MapCell::above_range, MapCell::no_value,
                                               MapCell::missing};
    return kinds;
}

void draw_cell_marker(cairo_t* cr, MapCell kind, const CellStyle& style, double x, double y, double r) {
    set_colour(cr, style.marker);
    cairo_new_sub_path(cr);
    if (kind == MapCell::below_range || kind == MapCell::above_range) {
        // A triangle pointing the way the answer lies.
        const double d = kind == MapCell::below_range ? 1.0 : -1.0, s = 1.25 * r;
        cairo_move_to(cr, x, y + d * s);
        cairo_line_to(cr, x - s, y - d * 0.75 * s);
        cairo_line_to(cr, x + s, y - d * 0.75 * s);
        cairo_close_path(cr);
    } else {
        cairo_arc(cr, x, y, r, 0, 2 * std::numbers::pi);
    }
    cairo_fill(cr);
}

void hatch(cairo_t* cr, double x0, double y0, double x1, double y1, double spacing, double width, Rgba colour) {
    set_colour(cr, colour);
    cairo_set_line_width(cr, width);
    // Lines at 45 degrees: x - y constant, stepping across the whole box.
    for (double c = x0 - (y1 - y0); c < x1; c += spacing) {
        cairo_move_to(cr, c, y1);
        cairo_line_to(cr, c + (y1 - y0), y0);
    }
    cairo_stroke(cr);
}

bool has_other_cells(const MapPanel& panel) {
    return std::any_of(panel.cells.begin(), panel.cells.end(), [](MapCell c) { return c != MapCell::value; });
}

namespace {

constexpr double kLegendRow = 22, kLegendText = 12, kSwatch = 16, kSwatchGap = 6, kEntryGap = 22;

// Where each entry of the legend goes: its kind, and its offset from the legend's corner.
struct Placed {
    MapCell kind;
    double dx, dy;
};
std::vector<Placed> legend_layout(cairo_t* cr, const Theme& theme, const MapPanel& panel, double width, double u,
                                  double body_px, Language language) {
    std::vector<Placed> out;
    double dx = 0, dy = 0;
    for (MapCell kind : other_cell_kinds()) {
        if (std::find(panel.cells.begin(), panel.cells.end(), kind) == panel.cells.end()) continue;
        const double w = (kSwatch + kSwatchGap) * u + text_width(cr, theme.font, text_size(kLegendText, u, body_px), cell_style(theme, kind, panel, language).label);
        if (dx > 0 && dx + w > width) dx = 0, dy += kLegendRow * u;  // on to the next row
        out.push_back({kind, dx, dy});
        dx += w + kEntryGap * u;
    }
    return out;
}

}  // namespace

double cell_legend_height(cairo_t* cr, const Theme& theme, const MapPanel& panel, double width, double u,
                          double body_px, Language language) {
    const std::vector<Placed> entries = legend_layout(cr, theme, panel, width, u, body_px, language);
    return entries.empty() ? 0.0 : entries.back().dy + kLegendRow * u + 8 * u;
}

void draw_cell_legend(cairo_t* cr, const Theme& theme, const MapPanel& panel, double x, double top, double width,
                      double u, double body_px, Language language, bool dots) {
    const double swatch = kSwatch * u;
    for (const Placed& e : legend_layout(cr, theme, panel, width, u, body_px, language)) {
        const CellStyle st = cell_style(theme, e.kind, panel, language);
        const double sx = x + e.dx, y = top + e.dy + 0.5 * kLegendRow * u;
        set_colour(cr, theme.text);
        text(cr, theme.font, text_size(kLegendText, u, body_px), sx + swatch + kSwatchGap * u, y, st.label, 0.0, 0.5);
        if (dots) {
            draw_cell_marker(cr, e.kind, st, sx + 0.5 * swatch, y, 4.0 * u);
            continue;
        }
        cairo_save(cr);
        cairo_rectangle(cr, sx, y - 0.5 * swatch, swatch, swatch);
        cairo_clip_preserve(cr);
        set_colour(cr, st.fill);
        cairo_fill(cr);
        if (st.hatched) hatch(cr, sx, y - 0.5 * swatch, sx + swatch, y + 0.5 * swatch, 4 * u, 1 * u, {0.45, 0.45, 0.47});
        cairo_restore(cr);
        set_colour(cr, theme.text);
        cairo_set_line_width(cr, 0.8 * u);
        cairo_rectangle(cr, sx, y - 0.5 * swatch, swatch, swatch);
        cairo_stroke(cr);
    }
}

std::vector<std::size_t> sorted_order(const std::vector<double>& values) {
    std::vector<std::size_t> order(values.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return values[a] < values[b]; });
    return order;
}

}  // namespace render

std::pair<int, int> sweep_map_size(const SweepMap& map) {
    const int panel = map.y ? 640 : 520;
    return {1000, panel * static_cast<int>(std::max<std::size_t>(1, map.panels.size()))};
}

void draw_sweep_map(cairo_t* cr, const SweepMap& map, double w, double h) {
    set_colour(cr, {map.theme.background.r, map.theme.background.g, map.theme.background.b, 1});
    cairo_paint(cr);
    const double ph = h / static_cast<double>(std::max<std::size_t>(1, map.panels.size()));
    for (std::size_t k = 0; k < map.panels.size(); ++k) {
        if (map.y) draw_heat_panel(cr, map, map.panels[k], 0, k * ph, w, ph);
        else draw_line_panel(cr, map, map.panels[k], 0, k * ph, w, ph);
    }
}

void require_map_format(const std::string& path) {
    const std::string ext = extension_of(path);
    if (ext != ".png" && ext != ".svg" && ext != ".pdf")
        throw InputError(Key::plot, path, "use .png, .svg or .pdf");
}

void write_sweep_map(const SweepMap& map_in, const std::string& path, const std::optional<PrintSize>& print,
                     RunOutputs* outputs) {
    require_map_format(path);
    const render::PictureFormat format = render::picture_format(path);
    SweepMap map = map_in;
    // Named copies: clang 14 (the fuzz build) cannot capture a structured binding.
    const auto size = sweep_map_size(map);
    int w = size.first, h = size.second;
    Page page;
    if (print) {
        // On a page: taller panels than on screen (a column is narrow) and no title or note over
        // them (the paper's caption says what the map shows).
        const double panel = map.y ? 0.78 : 0.62;
        const double aspect = panel * static_cast<double>(std::max<std::size_t>(1, map.panels.size()));
        const PrintLayout layout = print_layout(*print, aspect, format == render::PictureFormat::png);
        w = layout.width_px, h = layout.height_px, page = layout.page;
        map.text_px = layout.text_px;
    }
    const auto paint = [&](cairo_t* cr) { draw_sweep_map(cr, map, w, h); };
    if (format != render::PictureFormat::png) {
        render::write_vector(path, format, w, h, paint, page, outputs);
        return;
    }
    AtomicFile out(path, outputs);
    cairo::Surface surface(cairo_image_surface_create(CAIRO_FORMAT_RGB24, w, h));
    if (const cairo_status_t st = cairo_surface_status(surface.get()))
        throw SolverError(fmt::format("creating the image surface: {}", cairo_status_to_string(st)));
    {
        cairo::Context cr = cairo::make_context(surface.get());
        paint(cr.get());
        if (const cairo_status_t st = cairo_status(cr.get()))
            throw SolverError(fmt::format("drawing the map: {}", cairo_status_to_string(st)));
    }
    if (page.dpi > 0) {
        render::write_png(surface.get(), out, page.dpi);
    } else {
        errno = 0;
        if (const cairo_status_t st = cairo_surface_write_to_png(surface.get(), out.temp_path().c_str()))
            throw out.write_error(errno != 0 ? std::strerror(errno) : cairo_status_to_string(st));
    }
    out.commit();
}

}  // namespace dragon
