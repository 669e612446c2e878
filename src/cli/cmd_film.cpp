// dragon film STORY.toml -o film.mp4: a storyboard's shots assembled into one film (or one of
// its frames as a PNG, for a poster).
#include <optional>
#include <string>

#include <fmt/format.h>

#include "wording.hpp"
#include "commands.hpp"
#include "progress.hpp"
#include "status.hpp"
#include "print_flags.hpp"
#include "dragon/atomic_file.hpp"
#include "dragon/film.hpp"
#include "dragon/language.hpp"
#include "dragon/picture_size.hpp"
#include "dragon/video.hpp"

namespace dragon::cli {

namespace {
struct FilmCliOptions {
    std::string story, out, size;
    std::optional<double> fps, at;
    std::optional<int> crf, colours;
    std::optional<std::string> preset, tune;
    PrintFlags print;
    std::optional<std::string> lang;
    bool quiet = false;
};

}  // namespace

void register_film(CLI::App& app, Registry& reg) {
    auto opt = std::make_shared<FilmCliOptions>();
    CLI::App* sub = app.add_subcommand("film", "Assemble a storyboard's shots into one film (MP4, WebM, GIF) or a poster frame (PNG)");
    sub->add_option("storyboard", opt->story, "The storyboard, a .toml file (see assets/films/contest.toml)")->required();
    sub->add_option("-o,--out", opt->out, "Output: .mp4, .webm or .gif; .png with --at for one frame")->required();
    sub->add_option("--at", opt->at, "With a .png: the frame shown this many seconds into the film");
    sub->add_option("--size", opt->size, "Frame size WIDTHxHEIGHT, over the storyboard's [film] size (mp4 up to "
                                         "8192x4352, webm up to 4096x4096 in pixels)");
    opt->print.add_to(sub);  // a poster's size on a page (its shape stays the frame's)
    sub->add_option("--lang", opt->lang, "Language of the film's own words (clock, captions at the events, legend): en or "
                                         "zh, over the storyboard's [film] lang");
    sub->add_option("--fps", opt->fps, "Frames per second, over the storyboard's [film] fps");
    sub->add_option("--crf", opt->crf, fmt::format("Quality: H.264 0-51 (default {}), VP9 0-63 (default {})",
                                                   kDefaultCrf.h264, kDefaultCrf.vp9));
    sub->add_option("--preset", opt->preset, "libx264 preset (default faster)");
    sub->add_option("--tune", opt->tune, "libx264 tune (default animation)");
    sub->add_option("--colours", opt->colours, "GIF palette size, 2-256 (default 64)");
    add_quiet_flag(sub, opt->quiet);

    reg.runners["film"] = [opt](ToolRun& run) {
        Executor& ex = run.executor;
        RunOutputs& outputs = run.outputs;
        const bool poster = extension_of(opt->out) == ".png";
        if (poster && !opt->at) throw InputError("--out " + opt->out + " is a picture: give --at SECONDS, the moment of the film it shows");
        if (!poster && opt->at) {
            // A film's extension: --at is what does not belong; any other: the poster's extension is at fault.
            const std::string ext = extension_of(opt->out);
            if (ext != ".mp4" && ext != ".webm" && ext != ".gif")
                throw InputError(fmt::format("--out {} has extension '{}': the frame --at {} picks is written as a .png "
                                             "(a film is .mp4, .webm or .gif)", opt->out, ext, *opt->at));
            throw InputError(fmt::format("--at {} is not allowed for a film: it picks one frame for a .png", *opt->at));
        }
        VideoOptions vo;
        const VideoFormat format = poster ? VideoFormat::mp4 : video_format_for(opt->out);
        if (poster && (opt->crf || opt->preset || opt->tune || opt->colours))
            throw InputError("--crf, --preset, --tune and --colours are not allowed for a .png: they set a film's encoding");
        EncoderRequest encoder;  // the storyboard's size and rate are filled in below
        encoder.crf = opt->crf;
        encoder.preset = opt->preset;
        encoder.tune = opt->tune;
        encoder.colours = opt->colours;
        // Options of another format's encoder are refused before the storyboard is read.
        if (!poster) encoder_options(encoder, format);
        Storyboard board = load_storyboard(opt->story, run.assets, &outputs);
        print_warnings(board.warnings);
        if (!opt->size.empty()) {
            const PictureSize size = parse_picture_size(opt->size, kMaxVideoSide);
            board.film.width = size.width;
            board.film.height = size.height;
        }
        if (opt->fps) board.film.fps = *opt->fps;
        if (opt->lang) board.film.language = parse_language(*opt->lang);
        const std::optional<PrintSize> print = opt->print.resolve();
        if (print && !poster)
            throw InputError("a print size (--print, --width-in, --width-cm, --font-pt, --dpi) is for a poster frame "
                             "(.png with --at): a film's size is --size in pixels");
        if (print) {  // the frame's shape, at the poster's size on a page
            const PrintLayout layout =
                print_layout(*print, static_cast<double>(board.film.height) / board.film.width, true, kMaxVideoSide);
            board.film.width = layout.width_px, board.film.height = layout.height_px;
            board.film.text_px = layout.text_px;
        }
        encoder.width = board.film.width;
        encoder.height = board.film.height;
        encoder.fps = board.film.fps;
        if (poster) {  // one PNG: only the film's size and rate matter to it
            vo.width = encoder.width, vo.height = encoder.height, vo.fps = encoder.fps;
        } else {
            vo = encoder_options(encoder, format);
        }
        vo.executor = &ex;
        vo.outputs = &outputs;
        { AtomicFile probe(opt->out, &outputs); }  // an unwritable path fails here, before any work
        const Film film(board, &outputs);
        if (poster) {
            write_film_frame(film, *opt->at, opt->out, print ? print->dpi : 0.0, &outputs);
            run.wrote(opt->quiet, "wrote {}: frame {} of {} ({:.3f} s into the film), {}x{}", opt->out,
                   static_cast<int>(*opt->at * vo.fps), film.frame_count(), *opt->at, vo.width, vo.height);
            return 0;
        }
        const EncodeStats stats = [&] {
            ProgressLine progress("frames", opt->quiet);
            return write_film(film, opt->out, vo, [&progress](const Progress& p) { progress.update(p.done, p.total); });
        }();
        run.wrote(opt->quiet, "wrote {}: {}, {}, {}x{}, {:.2f} s of film ({:.1f} frames/s)", opt->out,
               count_of(static_cast<long long>(film.spans().size()), "shot"), count_of(stats.frames, "frame"), vo.width,
               vo.height, film.duration(), stats.fps());
        return 0;
    };
}

}  // namespace dragon::cli
