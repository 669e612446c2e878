// The path as cubic Bezier curves, for drawing guides without thousands of line segments, and
// only over the part of the path a picture shows: a guide's cost follows the view, not the
// path's length.
#pragma once

#include <utility>
#include <vector>

#include "dragon/path.hpp"
#include "dragon/render.hpp"
#include "clip.hpp"

namespace dragon::render {

// Distance from p to the box when outside (positive); minus the distance to its boundary when
// inside.
double signed_distance(const Box& box, const Vec2& p);

// The arc ranges within [s0, s1] over which the path may be inside the box, in order and
// merged: a superset, loose by at most `resolution` at either end of each range. Arc length is
// the path's own parameter, so a point at distance d from the box's boundary stays on its side
// for |s' - s| < d: the walk steps by that distance (at least `resolution`), and its cost follows
// how often the path passes the box, not how long the path is.
std::vector<std::pair<double, double>> arcs_in_box(const Path& path, double s0, double s1, const Box& box,
                                                   double resolution);

// [s0, s1] cut where the path changes piece (each piece can get its own colour): pieces follow
// one another along the path, so a bisection finds each change.
std::vector<std::pair<double, double>> split_by_piece(const Path& path, double s0, double s1);

// One run of Bezier segments over the arc range [s0, s1] that stays on one piece of the path.
struct GuideRun {
    int piece = 0;
    std::vector<Vec2> beziers;  // 1 + 3k points
};

// Hermite-to-Bezier over arc length: each segment turns by at most `max_turn` radians and is
// between `min_step` and `max_step` metres long (the turn limit gives way to min_step), so the
// curve is within a small fraction of a pixel of the path. Breaks where the path changes piece
// (each run can get its own colour).
std::vector<GuideRun> path_beziers(const Path& path, double s0, double s1, double max_step,
                                   double max_turn = 0.3, double min_step = 1e-6);

}  // namespace dragon::render
