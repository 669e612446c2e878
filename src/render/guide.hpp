// The path as cubic Bezier curves, for drawing guides without thousands of line segments.
#pragma once

#include <vector>

#include "dragon/path.hpp"
#include "dragon/render.hpp"

namespace dragon::render {

// One run of Bezier segments over the arc range [s0, s1] that stays on one piece of the path.
struct GuideRun {
    int piece = 0;
    std::vector<Vec2> beziers;  // 1 + 3k points
};

// Hermite-to-Bezier over arc length: each segment turns by at most `max_turn` radians and is at
// most `max_step` metres long, so the curve is within a small fraction of a pixel of the path.
// Breaks where the path changes piece (each run can get its own colour).
std::vector<GuideRun> path_beziers(const Path& path, double s0, double s1, double max_step,
                                   double max_turn = 0.3);

}  // namespace dragon::render
