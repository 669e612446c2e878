// The screen furniture drawn over a scene, in pixels: the annotation, the legend, the clock,
// captions, the scale bar, the colour bar and the inset. Each sits in its own corner or edge
// and says where it ended, so the next one can keep clear of it.
#pragma once

#include <vector>

#include <cairo.h>

#include "dragon/render.hpp"
#include "clip.hpp"
#include "render/paint.hpp"

namespace dragon::render {

// The sizes of one picture. On screen `u` scales lines and gaps (1 at 800 px on the shorter
// side) and `ut` scales text the same way but never below kMinTextPx for a 13 px label. At a
// print size (body_px > 0: Scene::text_px) the text is the size asked whatever the picture's
// size, and lines and gaps follow the text: u = ut = body_px / 12.
struct Units {
    double w = 0, h = 0, u = 1, ut = 1;
    double body_px = 0;
    // The size of a text set at `nominal` px in an 800 px picture.
    double text(double nominal) const { return text_size(nominal, ut, body_px); }
    static Units of(double w, double h, double body_px = 0);
};

// Width kept free on the right for the colour bar, px (0 without one).
double colour_bar_room(const Scene& s, const Units& un);
// Height of the annotation's box set within `right` px of the left edge, px: a title band
// that tall keeps the view clear of it.
double annotation_height(cairo_t* cr, const Scene& s, const Units& un, double right);

// How far from the left edge the legend reaches, px (0 without one): a view with room beside
// it is drawn clear of it.
double left_furniture(cairo_t* cr, const Scene& s, const Units& un, double right);

// Each returns the box it covers, px (an empty box at its corner when it drew nothing).
// The clock, top right, its right edge at `right`.
Box draw_clock(cairo_t* cr, const Scene& s, const Units& un, double right);
// The annotation top left (below `top`: under the clock in a narrow picture), wrapped short of
// `right` (the clock, or the picture's edge).
Box draw_annotation(cairo_t* cr, const Scene& s, const Units& un, double right, double top = 0.0);
// The legend below `top`, at the top left; or, where it would cover one of `marks` (what it
// explains: the touching benches' corners, px), in the first other corner left of `right` clear of them
// and of the furniture `taken` (the clock, the scale bar, the inset).
Box draw_legend(cairo_t* cr, const Scene& s, const Units& un, double top, const std::vector<std::vector<Vec2>>& marks = {},
                const std::vector<Box>& taken = {}, double right = 1e300);

// The scale bar, bottom left: its length in metres read at `px_per_m`.
Box draw_scale_bar(cairo_t* cr, const Scene& s, const Units& un, double px_per_m);
// The colour bar in the strip `room` px wide on the right, below `top`.
void draw_colour_bar(cairo_t* cr, const Scene& s, const Units& un, double room, double top);
// The inset in the bottom right corner, left of `right`, with the world box the main picture
// shows (lo, hi: metres) marked on it.
Box draw_inset(cairo_t* cr, const Scene& s, const Units& un, double right, const Vec2& lo, const Vec2& hi);
// Captions at the bottom, centred, between `left` and `right` if they fit there, else above
// everything at the bottom (whose top is `lift`).
void draw_captions(cairo_t* cr, const Scene& s, const Units& un, double left, double right, double lift);

// A backdrop of the theme's background behind screen text, so it reads over the drawing.
void backdrop(cairo_t* cr, const Theme& theme, double x, double y, double w, double h, double opacity = 0.82);

}  // namespace dragon::render
