// The chain solver for the first `count` handles only (handles 0..count-1 and the benches
// between them): what a check of one link needs without solving the whole chain behind it.
#pragma once

#include <vector>

#include "dragon/chain.hpp"

namespace dragon {

void solve_chain_front(const Path& path, const BenchSpec& spec, double head_arc, double head_speed, int count,
                       Frame& out);

// Only the angles (Place::u) of the whole chain's handles, head front first, on the plain
// spiral (its one piece): the same as solve_chain's, bit for bit, without the points, tangents,
// speeds and benches. What the proof of the untouched tail reads. False, leaving `theta` alone,
// on any other path.
bool solve_spiral_chain_angles(const Path& path, const BenchSpec& spec, double head_arc, std::vector<double>& theta);

}  // namespace dragon
