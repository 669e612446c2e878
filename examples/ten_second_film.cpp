// Ten seconds of film: the last 200 s of coiling in at 20x, 24 frames a second, H.264.
// Needs the video component.
#include <cstdio>

#include <dragon/video.hpp>

int main(int argc, char** argv) {
    const char* out = argc > 1 ? argv[1] : "coiling.mp4";
    const dragon::Simulation sim(dragon::Scenario{});
    const dragon::Clip clip{200.0, 400.0, 20.0, 0.0};  // from, to (simulated s), speedup, hold
    const dragon::Animation film(sim, clip, 24.0, dragon::SceneOptions{});
    dragon::VideoOptions options;
    options.width = 640;
    options.height = 360;
    const dragon::EncodeStats stats = dragon::write_video(film, out, options);
    std::printf("wrote %s: %d frames\n", out, stats.frames);
    return 0;
}
