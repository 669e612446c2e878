// Line plots with Cairo: axes with ticks at round numbers, labels, a legend, lines and markers,
// reference lines and text in data coordinates. Enough for the figures of a paper, no more.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <cairo.h>

#include "dragon/geometry.hpp"
#include "dragon/render.hpp"

namespace dragon {

class RunOutputs;  // dragon/atomic_file.hpp (io): the run a file written below belongs to, if given

// One series of a plot: its points, drawn as a line, as dots or both. Sizes are in the plot's
// units (plot_unit: px on a 900 x 560 plot).
struct PlotSeries {
    std::string label;        // legend entry; empty: not in the legend
    std::vector<Vec2> points; // data coordinates; a NaN y breaks the line
    Rgba colour;              // of the line and the dots
    double width_px = 1.8;    // the line's width
    bool line = true;         // joined by a line
    bool dashed = false;      // the line dashed
    bool markers = false;     // a dot at every point
    double marker_px = 3.0;   // the dots' radius
};

// Text at a data point, offset in pixels; a small dot marks the point if `dot`.
struct PlotLabel {
    Vec2 at = Vec2::Zero();  // data coordinates
    std::string text;        // the words
    Rgba colour;             // of the text and the dot
    double dx_px = 6;        // the text's offset from `at`, right
    double dy_px = -6;       // and down (negative: up)
    double size_px = 12;     // the text's size (at a print size: the plot's text_px)
    bool dot = false;        // mark `at` with a small dot
    double align = 0.0;  // 0 left, 0.5 centre, 1 right of the offset point
};

// A horizontal or vertical line across the plot, labelled at its end.
struct PlotRefLine {
    bool vertical = false;  // at x = value; else at y = value
    double value = 0;       // data coordinates
    std::string label;      // at its end; empty: none
    Rgba colour;            // of the line and its label
    bool dashed = true;     // dashed, else solid
};

// Where a plot's data area landed: its box in the surface's units (y0 at the top) and the data
// range it shows, to draw more in data coordinates.
struct PlotArea {
    double x0 = 0;    // the box's left
    double y0 = 0;    // top
    double x1 = 0;    // right
    double y1 = 0;    // bottom
    double x_lo = 0;  // the data's x at the left
    double x_hi = 1;  // at the right
    double y_lo = 0;  // the data's y at the bottom
    double y_hi = 1;  // at the top
    double px(double x) const { return x0 + (x - x_lo) / (x_hi - x_lo) * (x1 - x0); }  // a data x in the surface's units
    double py(double y) const { return y1 - (y - y_lo) / (y_hi - y_lo) * (y1 - y0); }  // a data y in the surface's units
};

// A line plot: what draw_plot draws.
struct Plot {
    Theme theme;                        // the colours and type
    std::string title;                  // above the plot; empty: none
    std::string note;                   // a smaller line under the title
    std::string x_label;                // the x axis's name and unit
    std::string y_label;                // the y axis's name and unit
    std::vector<PlotSeries> series;     // drawn in order, the first lowest
    std::vector<PlotRefLine> ref_lines;  // under the series
    std::vector<PlotLabel> labels;      // over everything
    std::optional<double> x_min;        // the axes' ranges; unset: the data's range, padded
    std::optional<double> x_max;        // unset: the data's, padded
    std::optional<double> y_min;        // unset: the data's, padded
    std::optional<double> y_max;        // unset: the data's, padded
    bool equal_aspect = false;  // one metre the same length on both axes (geometry)
    // No legend, or the data area's corner it goes in.
    enum class Legend { none, top_left, top_right, bottom_left, bottom_right };
    Legend legend = Legend::top_right;  // where the legend goes (at a print size: in rows above the frame)
    // Drawn first in the data area (clipped to it), under the reference lines and the series: a
    // heat map's cells, say. `u` is the plot's unit of line widths and text sizes, px.
    std::function<void(cairo_t* cr, const PlotArea& area, double u)> underlay;
    // A band under the data area, outside the value axis and sharing the x axis (its ticks go
    // under the band): marks at x values that have no y, such as a sweep's scenarios without an
    // answer. `strip_px` tall (0: no band, at the plot's scale), named by `strip_label` at its
    // left, drawn by `strip` in the band's box (its px() maps x; its y runs 0..1 upwards).
    double strip_px = 0;
    std::string strip_label;
    std::function<void(cairo_t* cr, const PlotArea& band, double u)> strip;
    // The body text's size (ticks, labels, legend), px, for a plot at a print size: the title
    // a fifth larger, lines and gaps following the text. 0: sizes follow the plot's box.
    double text_px = 0.0;
};

// A qualitative colour for series i (colour-blind-safe order, Okabe-Ito), darker or lighter to
// suit the theme's background.
Rgba series_colour(const Theme& theme, int i);

// The plot's unit of line widths and gaps in a box of w x h, px (the text's, at a print size).
double plot_unit(const Plot& plot, double w, double h);

// Draws the plot inside the box (x, y, w, h) of cr's current user space, background included;
// returns where its data area is.
PlotArea draw_plot(cairo_t* cr, const Plot& plot, double x, double y, double w, double h);
// All-or-nothing PNG of one plot.
void render_plot_png(const Plot& plot, int width_px, int height_px, const std::string& path,
                     RunOutputs* outputs = nullptr);

}  // namespace dragon
