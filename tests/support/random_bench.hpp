// A random bench make for randomized tests: a dozen or two benches of any reasonable size.
#pragma once

#include <random>

#include "dragon/scenario.hpp"

namespace dragon_test {

// 6 to 23 benches, bodies 1.2 to 2.5 m, a head up to 1.5 m longer, 0.15 to 0.35 m wide, holes
// 0.1 to 0.3 m from the ends.
inline void draw_bench(dragon::BenchSpec& b, std::mt19937& rng) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    b.bench_count = 6 + static_cast<int>(u(rng) * 18);
    b.body_length = 1.2 + 1.3 * u(rng);
    b.head_length = b.body_length + 1.5 * u(rng);
    b.width = 0.15 + 0.2 * u(rng);
    b.hole_offset = 0.1 + 0.2 * u(rng);
}

}  // namespace dragon_test
