// Where a video frame's time goes: the colour conversion, the encoder per preset, and the whole
// pipeline (draw on every core + convert + encode + mux). CPU time is for the whole process
// (the encoder's own threads included), so it reads the same on a busy machine; the fps
// counter is wall clock. scripts/bench-video.sh times the CLI end to end.
#include <filesystem>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

extern "C" {
#include <libavutil/frame.h>
}

#include "video/av_handles.hpp"
#include "render/cairo_handles.hpp"
#include "dragon/clip_plan.hpp"
#include "dragon/video.hpp"
#include "video/yuv_convert.hpp"

namespace {

using namespace dragon;

std::string scratch(const std::string& name) {
    return (std::filesystem::temp_directory_path() / ("dragon-bench-" + name)).string();
}

// 30 frames of the coil-in at 1 simulated second apart, drawn once.
std::vector<cairo::Surface> drawn_frames(int w, int h) {
    static const Simulation sim{Scenario{}};
    const Animation anim(sim, Clip{0.0, 29.0, 30.0}, 30, SceneOptions{});
    std::vector<cairo::Surface> out;
    for (int i = 0; i < anim.frame_count(); ++i) {
        out.emplace_back(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, w, h));
        cairo::Context cr = cairo::make_context(out.back().get());
        anim.paint(i, cr.get(), w, h);
        cairo_surface_flush(out.back().get());
    }
    return out;
}

// A w x h YUV 4:2:0 frame to convert into.
av::Frame yuv420_frame(int w, int h) {
    av::Frame yuv(av_frame_alloc());
    yuv->format = AV_PIX_FMT_YUV420P;
    yuv->width = w;
    yuv->height = h;
    av_frame_get_buffer(yuv.get(), 0);
    return yuv;
}

// A drawn surface converted into `yuv`, as the video writer converts each frame.
void convert(cairo_surface_t* s, AVFrame* yuv) {
    video::argb32_to_yuv420p(cairo_image_surface_get_data(s), cairo_image_surface_get_stride(s), yuv->width,
                             yuv->height,
                             {yuv->data[0], yuv->linesize[0], yuv->data[1], yuv->linesize[1], yuv->data[2],
                              yuv->linesize[2]});
    benchmark::DoNotOptimize(yuv->data[0][0]);
}

void BM_VideoArgbToYuv420p(benchmark::State& state) {
    const int w = static_cast<int>(state.range(0)), h = static_cast<int>(state.range(1));
    const auto frames = drawn_frames(w, h);
    const av::Frame yuv = yuv420_frame(w, h);
    size_t i = 0;
    for (auto _ : state) convert(frames[i++ % frames.size()].get(), yuv.get());
}
BENCHMARK(BM_VideoArgbToYuv420p)->Args({1280, 720})->Args({1920, 1080})->Unit(benchmark::kMillisecond);

// The README's coil-in film as `dragon video --to collision --speedup 20` draws it (legend,
// clock, captions, the contact marked at the end): drawing and colour conversion per frame,
// every frame of the clip in turn on one thread, without the encoder.
void BM_FilmDrawAndConvert(benchmark::State& state) {
    const int w = static_cast<int>(state.range(0)), h = static_cast<int>(state.range(1));
    static const Simulation sim{Scenario{}};
    SceneOptions scene;
    scene.theme = load_theme("light", DRAGON_SOURCE_DIR "/assets");
    ClipRequest request;
    request.to = "collision";
    request.speedup = 20.0;
    const ClipPlan plan = plan_clip(sim, request);
    FilmLook look;
    look.events = plan.events;
    const Animation anim(sim, plan.clip, 30.0, scene, plan.end_mark, look);
    cairo::Surface surface(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, w, h));
    const av::Frame yuv = yuv420_frame(w, h);
    int i = 0;
    for (auto _ : state) {
        {
            cairo::Context cr = cairo::make_context(surface.get());
            anim.paint(i++ % anim.distinct_frames(), cr.get(), w, h);
        }
        cairo_surface_flush(surface.get());
        convert(surface.get(), yuv.get());
    }
}
BENCHMARK(BM_FilmDrawAndConvert)->Args({1280, 720})->Args({1920, 1080})->Unit(benchmark::kMillisecond)->MinTime(2.0);

// Conversion + H.264 encoding of already drawn frames, 300 per run.
void encode(benchmark::State& state, const char* preset) {
    const int w = static_cast<int>(state.range(0)), h = static_cast<int>(state.range(1));
    const auto frames = drawn_frames(w, h);
    VideoOptions opt;
    opt.width = w;
    opt.height = h;
    opt.preset = preset;
    const std::string path = scratch("encode.mp4");
    for (auto _ : state) {
        VideoWriter writer(path, opt);
        for (int i = 0; i < 300; ++i) writer.write(frames[static_cast<size_t>(i) % frames.size()].get());
        writer.finish();
    }
    std::filesystem::remove(path);
    state.counters["fps"] = benchmark::Counter(300.0 * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
void BM_VideoEncodeUltrafast(benchmark::State& state) { encode(state, "ultrafast"); }
void BM_VideoEncodeVeryfast(benchmark::State& state) { encode(state, "veryfast"); }
BENCHMARK(BM_VideoEncodeUltrafast)->Args({1280, 720})->Args({1920, 1080})->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()->UseRealTime()->Iterations(1);
BENCHMARK(BM_VideoEncodeVeryfast)->Args({1280, 720})->Args({1920, 1080})->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()->UseRealTime()->Iterations(1);

// The target: 300 frames at 30 fps, default options, drawing included.
void BM_VideoEndToEnd(benchmark::State& state) {
    const Simulation sim{Scenario{}};
    const Animation anim(sim, Clip{0.0, 299.0, 30.0}, 30, SceneOptions{});
    VideoOptions opt;
    opt.width = static_cast<int>(state.range(0));
    opt.height = static_cast<int>(state.range(1));
    const std::string path = scratch("end-to-end.mp4");
    for (auto _ : state) benchmark::DoNotOptimize(write_video(anim, path, opt));
    std::filesystem::remove(path);
    state.counters["fps"] = benchmark::Counter(anim.frame_count() * static_cast<double>(state.iterations()),
                                               benchmark::Counter::kIsRate);
}
BENCHMARK(BM_VideoEndToEnd)->Args({1280, 720})->Args({1920, 1080})->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()->UseRealTime()->Iterations(1);

}  // namespace
