// The panels of a sweep's map (dragon/sweep_map.hpp), each drawn into its own box.
#pragma once

#include <vector>

#include <cairo.h>

#include "dragon/sweep_map.hpp"

namespace dragon::render {

// How a cell that holds no value is shown, with its legend text; the same in both kinds of panel.
struct CellStyle {
    Rgba fill;
    bool hatched = false;
    std::string label;
    Rgba marker;  // a line plot's dot for such a scenario: strong enough to see as a dot
};
CellStyle cell_style(const Theme& theme, MapCell cell, const MapPanel& panel, Language language = Language::en);
// Every kind but values, in the order the legend lists them.
const std::vector<MapCell>& other_cell_kinds();
// A line plot's marker for a scenario of this kind at (x, y), radius r: a dot, or a triangle
// pointing down (answer below the range) or up (above it).
void draw_cell_marker(cairo_t* cr, MapCell kind, const CellStyle& style, double x, double y, double r);
// Diagonal hatching across the current clip, lines `spacing` apart.
void hatch(cairo_t* cr, double x0, double y0, double x1, double y1, double spacing, double width, Rgba colour);
// The legend of the cell kinds other than values that the panel holds (a swatch and its text
// each), in rows as wide as `width` allows, from (x, top): its height, and the drawing.
// `body_px`: the map's text size at a print size (SweepMap::text_px), 0 on screen.
double cell_legend_height(cairo_t* cr, const Theme& theme, const MapPanel& panel, double width, double u,
                          double body_px, Language language);
// `dots`: each entry's swatch is its marker (line plots), else its cell.
void draw_cell_legend(cairo_t* cr, const Theme& theme, const MapPanel& panel, double x, double top, double width,
                      double u, double body_px, Language language, bool dots = false);
// Whether the panel holds cells of any kind but values.
bool has_other_cells(const MapPanel& panel);

// The order that sorts `values` increasingly.
std::vector<std::size_t> sorted_order(const std::vector<double>& values);

void draw_heat_panel(cairo_t* cr, const SweepMap& map, const MapPanel& panel, double x, double y, double w, double h);
void draw_line_panel(cairo_t* cr, const SweepMap& map, const MapPanel& panel, double x, double y, double w, double h);

}  // namespace dragon::render
