// A random bench make for randomized tests: a dozen or two benches of any reasonable size.
#pragma once

#include <random>

#include "dragon/scenario.hpp"

namespace dragon_test {

// 6 to 23 benches, bodies 1.2 to 2.5 m, a head up to 1.5 m longer, 0.15 to 0.35 m wide, holes
// 0.1 to 0.3 m from the ends. `u()` draws uniformly from [0, 1): a seeded generator in the
// tests, the input's bytes in the fuzz targets.
template <class Uniform>
void draw_bench_with(dragon::BenchSpec& b, Uniform& u) {
    b.bench_count = 6 + static_cast<int>(u() * 18);
    b.body_length = 1.2 + 1.3 * u();
    b.head_length = b.body_length + 1.5 * u();
    b.width = 0.15 + 0.2 * u();
    b.hole_offset = 0.1 + 0.2 * u();
}

inline void draw_bench(dragon::BenchSpec& b, std::mt19937& rng) {
    std::uniform_real_distribution<double> dist(0.0, 1.0);
    auto u = [&] { return dist(rng); };
    draw_bench_with(b, u);
}

}  // namespace dragon_test
