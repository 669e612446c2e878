// Contour lines of a function sampled on a rectangular grid, by marching squares.
#pragma once

#include <vector>

#include "dragon/geometry.hpp"

namespace dragon::render {

// The lines where z = level, as polylines in data coordinates (closed ones end where they
// start). z[ix * ys.size() + iy] is the value at (xs[ix], ys[iy]); xs and ys increase. A value
// that is NaN is no value: no line crosses a square with such a corner. Between samples z is
// taken as linear along each edge; a saddle square is resolved by the mean of its corners.
std::vector<std::vector<Vec2>> contour_lines(const std::vector<double>& xs, const std::vector<double>& ys,
                                             const std::vector<double>& z, double level);

}  // namespace dragon::render
