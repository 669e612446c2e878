// The chain solver for the first `count` handles only (handles 0..count-1 and the benches
// between them): what a check of one link needs without solving the whole chain behind it.
#pragma once

#include "dragon/chain.hpp"

namespace dragon {

void solve_chain_front(const Path& path, const BenchSpec& spec, double head_arc, double head_speed, int count,
                       Frame& out);

}  // namespace dragon
