// The picture's view of the world and the shapes drawn through it, shared by draw() and the
// marks (overlays, markers) drawn over the dragon.
#pragma once

#include <vector>

#include <cairo.h>

#include "dragon/render.hpp"
#include "clip.hpp"

namespace dragon::render {

// World (metres, y up) to device pixels (y down), aspect ratio kept; and the boxes (pixels)
// that keep Cairo's work to the picture (see clip.hpp): shapes inside `tame` go to Cairo as they
// are, the rest are cut to `cut` first.
struct View {
    double cx, cy, scale, ox, oy;
    Box tame, cut;
    Vec2 px(const Vec2& p) const { return {ox + (p.x() - cx) * scale, oy - (p.y() - cy) * scale}; }
};

void polygon_path(cairo_t* cr, const std::vector<Vec2>& pts);
// A bench's rectangle, cut to the picture when it reaches far outside.
void rect_path(cairo_t* cr, const View& v, const Rect& r);
bool tame_circle(const View& v, const Vec2& p, double r);
bool off_picture(const View& v, const Vec2& p, double r);
// A disk of radius r px about p, to fill; its outline, to stroke.
void circle_path(cairo_t* cr, const View& v, const Vec2& p, double r);
void ring_path(cairo_t* cr, const View& v, const Vec2& p, double r);
void set_dash(cairo_t* cr, bool dashed, double u);
// The part of the world the picture shows, widened by `pad_px` pixels on every side.
Box world_box(const View& v, double w, double h, double pad_px);

// The polylines (arrows too) and markers of a scene, and its contact mark.
void draw_overlays(cairo_t* cr, const Scene& s, const View& v, double u);
void draw_collision(cairo_t* cr, const Scene& s, const View& v, double u);

}  // namespace dragon::render
