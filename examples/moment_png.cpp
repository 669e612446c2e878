// A picture of the dragon 300 s into coiling in, each bench coloured by its speed.
// Needs the render component.
#include <cstdio>

#include <dragon/render.hpp>

int main(int argc, char** argv) {
    const char* out = argc > 1 ? argv[1] : "dragon_300s.png";
    const dragon::Simulation sim(dragon::Scenario{});
    dragon::SceneOptions options;
    options.colour_by_speed = true;
    const dragon::Scene scene = dragon::make_scene(sim, sim.frame(300.0), options);
    dragon::render_png(scene, 800, 800, out);
    std::printf("wrote %s\n", out);
    return 0;
}
