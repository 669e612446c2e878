// Shapes cut to the picture before they reach Cairo. Cairo keeps coordinates in 24.8 fixed
// point (about +-8 million pixels: beyond that they wrap around) and flattens a curve into a
// number of lines that grows with the square root of its radius, so in a close-up the 4.5 m
// turning-space circle or a 2.2 m board, thousands of picture widths across, would be drawn
// wrong and slowly. draw() passes shapes within a few picture sizes of the picture to Cairo as
// they are and cuts the rest to a box just outside the picture first, here, in pixels.
#pragma once

#include <algorithm>
#include <vector>

#include "dragon/geometry.hpp"

namespace dragon::render {

// An axis-aligned box: world metres for the guides, pixels for the cuts below.
struct Box {
    Vec2 lo = Vec2::Zero(), hi = Vec2::Zero();
    double extent() const { return std::max(hi.x() - lo.x(), hi.y() - lo.y()); }
    bool holds(const Vec2& p) const { return p.x() >= lo.x() && p.x() <= hi.x() && p.y() >= lo.y() && p.y() <= hi.y(); }
    Box grown(double by) const { return {{lo.x() - by, lo.y() - by}, {hi.x() + by, hi.y() + by}}; }
};

// The part of a convex polygon inside the box (Sutherland-Hodgman, one side at a time); empty
// when they do not meet.
std::vector<Vec2> clip_polygon(std::vector<Vec2> polygon, const Box& box);

// The pieces of a polyline inside the box (each segment cut by Liang-Barsky; consecutive
// pieces that meet are joined).
std::vector<std::vector<Vec2>> clip_polyline(const std::vector<Vec2>& line, bool closed, const Box& box);

// The disk of radius r about c, inside the box, as a polygon whose curved edges stay within
// `tolerance` of the circle. Costs what the box shows: a circle far larger than the box is
// sampled only over the angles that cross it.
std::vector<Vec2> disk_in_box(const Vec2& c, double r, const Box& box, double tolerance);
// The circle's outline inside the box, as polylines within `tolerance` of it.
std::vector<std::vector<Vec2>> circle_in_box(const Vec2& c, double r, const Box& box, double tolerance);

}  // namespace dragon::render
