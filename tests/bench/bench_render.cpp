// Drawing cost: one 1920 x 1080 frame of the whole dragon onto an image surface (no PNG
// compression), and building the scene from a frame.
#include <benchmark/benchmark.h>

#include "render/cairo_handles.hpp"
#include "dragon/render.hpp"

namespace {

using namespace dragon;

void draw_frame(benchmark::State& state, bool speed_colours) {
    const Simulation sim(Scenario{});
    SceneOptions o;
    o.theme = load_theme("light", DRAGON_SOURCE_DIR "/assets");
    o.colour_by_speed = speed_colours;
    const Scene scene = make_scene(sim, sim.frame(300.0), o);
    cairo::Surface surface(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 1920, 1080));
    cairo::Context cr = cairo::make_context(surface.get());
    for (auto _ : state) {
        draw(cr.get(), scene, 1920, 1080);
        cairo_surface_flush(surface.get());  // make sure the pixels are really there
        benchmark::DoNotOptimize(cairo_image_surface_get_data(surface.get()));
    }
    state.counters["fps"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

void BM_RenderWholeDragon1080p(benchmark::State& state) { draw_frame(state, false); }
void BM_RenderWholeDragon1080pSpeedColours(benchmark::State& state) { draw_frame(state, true); }

// What a video frame costs besides drawing: solving the chain and building the display list.
void BM_RenderMakeScene(benchmark::State& state) {
    const Simulation sim(Scenario{});
    const Frame f = sim.frame(300.0);
    const SceneOptions o;
    for (auto _ : state) benchmark::DoNotOptimize(make_scene(sim, f, o));
}

}  // namespace

BENCHMARK(BM_RenderWholeDragon1080p)->Unit(benchmark::kMillisecond)->MinTime(1.0);
BENCHMARK(BM_RenderWholeDragon1080pSpeedColours)->Unit(benchmark::kMillisecond)->MinTime(1.0);
BENCHMARK(BM_RenderMakeScene)->Unit(benchmark::kMicrosecond);
