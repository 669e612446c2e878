// The contest's dragon 300 s into coiling in: where its handles are and how fast they move.
// Needs only the core component.
#include <cstdio>

#include <dragon/chain.hpp>

int main() {
    const dragon::Simulation sim(dragon::Scenario{});  // the contest's defaults (CUMCM 2024 A)
    const dragon::Frame frame = sim.frame(300.0);
    for (std::size_t i : {0u, 1u, 51u, 101u, 151u, 201u, 223u}) {
        const dragon::Handle& h = frame.handles[i];
        std::printf("handle %3zu  x %10.6f  y %10.6f  speed %.6f m/s\n", i, h.pos.x(), h.pos.y(), h.speed);
    }
    // Where the motion ends: past this moment a handle would have to jump.
    const dragon::ValidRange valid = sim.valid_range();
    std::printf("valid until t = %.9f s\n", valid.to);
    return 0;
}
