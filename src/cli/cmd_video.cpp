// dragon video: a film of the dragon, MP4 (H.264), WebM (VP9) or GIF by the file's extension.
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "commands.hpp"
#include "report.hpp"
#include "progress.hpp"
#include "render_flags.hpp"
#include "scenario_flags.hpp"
#include "status.hpp"
#include "window_flags.hpp"
#include "wording.hpp"
#include "dragon/atomic_file.hpp"
#include "dragon/clip_plan.hpp"
#include "dragon/look.hpp"
#include "dragon/path.hpp"
#include "dragon/picture_size.hpp"
#include "dragon/render.hpp"
#include "dragon/tables.hpp"
#include "dragon/video.hpp"

namespace dragon::cli {

namespace {

struct VideoCliOptions {
    ScenarioFlags scenario;
    std::string out;
    std::optional<std::string> from;
    std::string to;
    double fps = 30.0;
    double speedup = 10.0;
    std::optional<double> hold;
    std::string size = "1280x720";
    std::optional<int> crf;
    std::optional<std::string> preset, tune;
    std::optional<int> threads;
    std::optional<int> colours;
    bool follow_head = false;
    std::optional<double> zoom;
    std::string theme = "light";
    std::string lang = "en";
    bool colour_by_speed = false;
    bool no_guides = false, no_text = false, no_legend = false, no_inset = false;
    bool quiet = false;
};

}  // namespace

void register_video(CLI::App& app, Registry& reg) {
    auto opt = std::make_shared<VideoCliOptions>();
    CLI::App* sub = app.add_subcommand("video", "Animate to MP4 (H.264), WebM (VP9) or GIF");
    opt->scenario.add_to(sub, ScenarioUse::drawing(), reg);
    sub->add_option("-o,--out", opt->out, "Output file: .mp4, .webm or .gif")->required();
    sub->add_option("--from", opt->from, "First moment: simulated s, or head travel with m (default 0; -100m on the "
                                         "turnaround path)")->type_name("T|Xm");
    sub->add_option("--to", opt->to,
                    "Last moment: simulated s, head travel with m, or collision (first contact, marked), boundary "
                    "(head at the turning space), end (the end of the valid motion: the spiral's centre, or where "
                    "a handle would have to jump). Default: collision; 100m on the turnaround path");
    sub->add_option("--fps", opt->fps, "Frames per second of video, 0.01 to 240 (default 30)");
    sub->add_option("--speedup", opt->speedup, "Simulated seconds per second of video (default 10)");
    sub->add_option("--hold", opt->hold, "Seconds the last moment stays on screen, 0..3600, drawn once (default 1 at a collision, else 0)");
    sub->add_option("--size", opt->size, "Picture size in pixels, WIDTHxHEIGHT (default 1280x720; even for mp4/webm; "
                                         "mp4 up to 8192x4352, webm up to 4096x4096 in pixels)");
    sub->add_option("--crf", opt->crf,
                    fmt::format("Quality, lower is better: H.264 0-51 (default {}), VP9 0-63 (default {}); not for GIF",
                                kDefaultCrf.h264, kDefaultCrf.vp9));
    sub->add_option("--preset", opt->preset, "libx264 preset (.mp4), ultrafast .. veryslow (default faster: with tune animation, "
                                         "8 reference frames and subme 2 over it, which suit the dragon; any other "
                                         "is x264's own; ultrafast encodes ~2x faster into ~5x larger files)");
    sub->add_option("--tune", opt->tune, "libx264 tune: animation (default, for line art), film, stillimage, "
                                       "grain, psnr, ssim, fastdecode, zerolatency or none");
    sub->add_option("--threads", opt->threads, "Encoder threads, 0 = automatic (default); above 3840x2160 at most 2 "
                                               "for mp4 and 8 for webm, to stay under 2 GB");
    sub->add_option("--colours", opt->colours, "GIF palette size, 2-256 (default 64, 256 with --speed-colours)");
    sub->add_flag("--follow-head", opt->follow_head, "Keep the head in the middle of the picture (a 12 m square unless --zoom)");
    sub->add_option("--zoom", opt->zoom, "Show a square of this many metres, around the head with --follow-head, "
                                         "else around the centre (default: the whole dragon over the clip)");
    sub->add_option("--theme", opt->theme, "Colour theme: light, dark or a .toml file (default light)");
    add_language_flag(sub, opt->lang);
    sub->add_flag("--speed-colours", opt->colour_by_speed, "Colour each bench by its speed, with a colour bar");
    sub->add_flag("--no-guides", opt->no_guides, "Leave out the path and the turning-space circle");
    sub->add_flag("--no-text", opt->no_text, "Leave out all text (clock, captions, legend, labels)");
    sub->add_flag("--no-legend", opt->no_legend, "Leave out the key to the colours");
    sub->add_flag("--no-inset", opt->no_inset, "Leave out the small whole-dragon picture of a followed or zoomed view");
    add_quiet_flag(sub, opt->quiet);

    reg.runners["video"] = [opt, sub](ToolRun& run) {
        Executor& ex = run.executor;
        RunOutputs& outputs = run.outputs;
        // Everything that can be checked without simulating first, so bad options fail at once
        // and leave no file.
        const VideoFormat format = video_format_for(opt->out);
        // (--width is the scenario's board width, so the picture's size is an option of its own.)
        const PictureSize size = parse_picture_size(opt->size, kMaxVideoSide);
        EncoderRequest encoder;
        encoder.width = size.width;
        encoder.height = size.height;
        encoder.fps = opt->fps;
        encoder.crf = opt->crf;
        encoder.preset = opt->preset;
        encoder.tune = opt->tune;
        encoder.threads = opt->threads;
        encoder.colours = opt->colours;
        encoder.speed_colours = opt->colour_by_speed;
        VideoOptions vo = encoder_options(encoder, format);
        vo.executor = &ex;
        LookRequest look_asked;
        look_asked.theme = opt->theme;
        look_asked.lang = opt->lang;
        look_asked.speed_colours = opt->colour_by_speed;
        look_asked.guides = !opt->no_guides;
        look_asked.text = !opt->no_text;
        look_asked.zoom = opt->zoom;
        look_asked.follow_head = opt->follow_head;
        const SceneOptions scene = clip_scene_options(look_asked, run.assets, &outputs);
        vo.outputs = &outputs;
        { AtomicFile probe(opt->out, &outputs); }  // an unwritable path fails here, before any work
        const Scenario s = opt->scenario.resolve(&outputs);

        const Simulation sim(s);
        const ClipPlan plan =
            plan_clip(sim, {opt->from, opt->to, opt->speedup, opt->hold, scene.language}, {"--from", "--to"});
        const Clip& clip = plan.clip;
        FilmLook look;
        look.legend = !opt->no_legend;
        look.inset = !opt->no_inset;
        look.events = plan.events;
        const Animation anim(sim, clip, vo.fps, scene, plan.end_mark, look);
        if (opt->zoom) require_zoom_resolves(anim, vo.width, vo.height, *opt->zoom);

        const EncodeStats stats = [&] {
            ProgressLine progress("frames", opt->quiet);
            return write_video(anim, opt->out, vo, [&progress](const Progress& p) { progress.update(p.done, p.total); });
        }();
        run.wrote(opt->quiet, "wrote {}: {}, {}x{}, {:.2f} s of video for t = {:.6f} .. {:.6f} s ({:.1f} frames/s)",
               opt->out, count_of(stats.frames, "frame"), vo.width, vo.height, stats.frames / vo.fps, clip.from, clip.to, stats.fps());
        if (plan.end_mark)
            fmt::print("benches {} and {} touch at t = {:.6f} s\n", plan.end_mark->bench_a, plan.end_mark->bench_b,
                       clip.to);
        return 0;
    };
}

}  // namespace dragon::cli
