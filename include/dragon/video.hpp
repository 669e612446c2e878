// Videos: a streaming encoder (H.264 in MP4, VP9 in WebM, animated GIF) and the pipeline that
// renders a simulation into it on the caller's executor, never holding more than a few frames.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <cairo.h>

#include "dragon/chain.hpp"
#include "dragon/executor.hpp"
#include "dragon/render.hpp"

namespace dragon {

namespace render {
class BackdropCache;  // render/backdrop.hpp, the library's own
}
class RunOutputs;  // dragon/atomic_file.hpp (io)

// The container and codec, chosen by the output file's extension.
enum class VideoFormat {
    mp4,   // .mp4: H.264 (libx264), yuv420p
    webm,  // .webm: VP9 (libvpx-vp9), yuv420p
    gif,   // .gif: 256-colour palette (median cut over sample frames), no dithering
};
// Throws InputError naming the extension and the allowed ones.
VideoFormat video_format_for(const std::string& path);
const char* to_string(VideoFormat f);  // "mp4", "webm", "gif"

// The quality each codec gets when VideoOptions::crf is unset.
struct DefaultCrf {
    int h264;  // libx264's constant rate factor
    int vp9;   // libvpx-vp9's
};
inline constexpr DefaultCrf kDefaultCrf{23, 35};  // measured on the dragon's films by scripts/bench-video.sh

// The rates a video can have, frames per second: a frame at least every 100 s (GIF stores a
// frame's delay in 1/100 s in 16 bits, 655 s at most, and the MP4 muxer refuses the durations of
// rates below ~1e-5), at most 240 a second.
inline constexpr double kMinVideoFps = 0.01;
inline constexpr double kMaxVideoFps = 240.0;
// The largest side of a video, px: memory and the codecs' limits, not taste.
inline constexpr int kMaxVideoSide = 8192;
// The most pixels a WebM frame may have (4096x4096, 16.8 million). libvpx's VP9 encoder keeps
// a token buffer of ~48 bytes a pixel and its reference frames besides: ~1.4 GB resident at
// this size (scripts/limits.sh), and 7.7 GB was measured at 8192x8192. Every size
// a video accepts stays under 2 GB resident (H.264 allows 8192x4352 at most: ~1 GB).
inline constexpr long kMaxWebmPixels = 4096L * 4096L;
// The frames being drawn and waiting for the encoder take at most this much memory: two per
// drawing worker, up to 8 workers at small sizes, fewer as the frames grow (3 at 3840x2160, 2 at
// 4096x4096, one with its two frames from 8192x4352 up: a 8192x8192 frame is 256 MiB). Above 3840x2160 the
// encoders are held to a few frames in flight too (one reference frame and no B-frames for
// H.264, at most 2 encoder threads for H.264 and 8 for VP9).
inline constexpr long kMaxFrameRingBytes = 256L << 20;
// The most frames a film may have: far beyond any sensible film (an hour at 240 fps is 864 000);
// stops a typo from running for days.
inline constexpr int kMaxFilmFrames = 1'000'000;

// How a video is encoded: its size, rate, quality and the codec's settings.
struct VideoOptions {
    int width = 1280;   // pixels; even for mp4 and webm (yuv420p halves the chroma planes)
    int height = 720;   // pixels; even for mp4 and webm
    double fps = 30.0;  // frames per second of the video, 0.01 to 240
    // Quality: constant rate factor; lower is better and larger. None: the codec's default here
    // (H.264: 23, VP9: 35; see kDefaultCrf). GIF has none.
    std::optional<int> crf;
    // libx264 preset (ultrafast .. veryslow) and tune (animation, film, stillimage, ...; "none"
    // for x264's own). The defaults suit a dragon's films on two cores: "faster" with tune
    // "animation", and over them (with these two only) 8 reference frames and sub-pixel
    // refinement at level 2. The chain moves along its own path, so each bench soon lies where
    // another lay and a long reference list finds it. Measured by scripts/bench-video.sh on the
    // README's coil-in film (720p, 650 frames) against a lossless encode: 2.9 Mbit/s at 40.6 dB
    // (plain "faster": 3.2 Mbit/s at 40.6 dB) for two thirds of the encoder's CPU; at speedup
    // 10 half the bits; "ultrafast" at crf 20 made 15.9 Mbit/s.
    std::string preset = "faster";
    std::string tune = "animation";
    // Seconds between key frames (H.264, VP9): a player can seek to one in at most this long.
    // Flat drawings that change a little per frame cost a large key frame each; 10 s keeps them
    // a small share of a film's bits.
    double keyframe_seconds = 10.0;
    int threads = 0;    // encoder threads, 0 = the codec decides
    // GIF palette size, 2..256. Fewer colours make much smaller files of flat drawings (64
    // instead of 256: a fifth smaller, 0.1 dB lower); the palette keeps small distinct patches
    // (head, tail) down to ~32. Speed colours need more for a smooth ramp (the CLI asks 256).
    int colours = 64;
    // The workers frames are drawn on (encode_frames, write_video, write_film): at most 8 of its
    // workers draw, and the one that finds the next frame drawn encodes it. Null: the
    // calling thread alone. The codec's own threads are `threads`, above.
    Executor* executor = nullptr;
    // The run the file belongs to (put in place when it commits; see dragon/atomic_file.hpp).
    // Null: put in place as soon as it is written.
    RunOutputs* outputs = nullptr;
};
// Throws InputError for a size or rate the format cannot take (odd size for yuv420p, fps out
// of range, an unknown preset, a crf or palette size out of range, a crf for GIF). Its fields:
// "video size", "frame rate", "H.264 quality (crf)" (VP9, GIF likewise), "encoder preset",
// "encoder tune", "key frame interval", "palette colours", "encoder threads".
void validate(const VideoOptions& opt, VideoFormat format);

// The GIF palette's size when none is asked: VideoOptions::colours, or this many for speed
// colours, whose ramp needs them to stay smooth.
inline constexpr int kSpeedColoursPalette = 256;

// What a caller asked of the encoder (the video command's flags, Python's keywords): the
// unset values are VideoOptions' defaults. An option of another format's encoder is refused,
// not ignored: a preset for .webm would do nothing.
struct EncoderRequest {
    int width = VideoOptions{}.width;    ///< pixels
    int height = VideoOptions{}.height;  ///< pixels
    double fps = VideoOptions{}.fps;     ///< frames per second
    std::optional<int> crf;              ///< quality (VideoOptions::crf); unset: the codec's default
    std::optional<std::string> preset;  // .mp4 only (Key::preset)
    std::optional<std::string> tune;    // .mp4 only (Key::tune)
    std::optional<int> threads;          ///< encoder threads (VideoOptions::threads)
    std::optional<int> colours;  // .gif only (Key::colours)
    bool speed_colours = false;  // frames coloured by speed: a GIF's default palette is kSpeedColoursPalette
};
// The options for `format`, checked (validate()), or InputError naming the key at fault.
VideoOptions encoder_options(const EncoderRequest& request, VideoFormat format);

// Encodes frames to a file as they come; never holds more than the codec's own look-ahead.
// Writes to a temporary file beside the target, renamed over it by finish(): an error, an
// exception or a kill before finish() leaves no file at the target.
class VideoWriter {
public:
    // Checks the options and the path (InputError), then opens the muxer and encoder.
    VideoWriter(const std::string& path, const VideoOptions& opt);
    ~VideoWriter();  // without finish(): drops the temporary file. Never throws.
    VideoWriter(const VideoWriter&) = delete;
    VideoWriter& operator=(const VideoWriter&) = delete;

    VideoFormat format() const;              // from the path's extension
    const VideoOptions& options() const;     // as checked

    // GIF only (a no-op for the others): lets a picture's colours shape the palette. Call it
    // before the first frame, with frames spread over the clip (its first, middle and last,
    // say); without it the first frame alone decides.
    void add_palette_sample(const std::uint8_t* argb32, int stride);

    // One frame of exactly width x height pixels in Cairo's ARGB32 layout (native-endian
    // 32-bit, premultiplied; it must be opaque), rows `stride` bytes apart.
    void write(const std::uint8_t* argb32, int stride);
    // The same from a Cairo image surface (flushed here).
    void write(cairo_surface_t* surface);
    // The last frame written, once more (a held picture): no conversion, straight to the encoder.
    void repeat();

    // Drains the encoder, writes the trailer and renames the file into place.
    void finish();

    int frames_written() const;  // frames handed to the encoder so far, repeats included

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};


// Progress of a long encode: frames done of total, seconds since the start.
struct Progress {
    int done = 0;          // frames encoded
    int total = 0;         // frames to encode
    double elapsed = 0.0;  // s of wall time
};
// Hears a long encode's progress (may be empty).
using ProgressFn = std::function<void(const Progress&)>;

// Paints frame `index` (0-based) onto an ARGB32 image surface of the video's size; it must
// paint every pixel opaque and depend on the index alone. Called on the executor's workers,
// several at once (so it must be safe to call concurrently), roughly in order; for a GIF also
// beforehand, on the caller's thread, for the palette's sample frames.
using PaintFn = std::function<void(int index, cairo_t* cr)>;

// What an encode did and how fast.
struct EncodeStats {
    int frames = 0;        // frames encoded
    double seconds = 0.0;  // wall time, end to end
    // Frames encoded a second of wall time (0 before any time passed).
    double fps() const { return seconds > 0 ? frames / seconds : 0.0; }
};

// Renders `frame_count` frames with `paint` on opt.executor's workers (the default executor's,
// one per core, when it is null; at most 8) and encodes them in order, through a ring of 2
// reusable surfaces per worker: whichever worker finds the next frame drawn encodes it, so
// drawing and encoding overlap and every worker works. Only frames 0 .. painted - 1 are painted
// (all of them when `painted` is 0): the rest repeat frame painted - 1, drawn once and handed to
// the encoder again (a held last moment costs its encoding alone). GIF palettes are sampled
// from the first, middle and last frames first. `progress` is called once a frame, in order,
// one call at a time, from the worker encoding (the held frames' from this thread). An error
// on any worker stops them all and is rethrown here; the target is written only if every frame
// made it.
EncodeStats encode_frames(const std::string& path, const VideoOptions& opt, int frame_count,
                          const PaintFn& paint, const ProgressFn& progress = {}, int painted = 0);

// ---- Films of a simulation -------------------------------------------------------------------

// A stretch of simulated time shown as a film.
struct Clip {
    double from = 0.0;     // simulated seconds
    double to = 0.0;       // simulated seconds, after `from`; the last frame shows exactly this moment
    double speedup = 1.0;  // simulated seconds per second of video
    double hold = 0.0;     // seconds of video the last moment stays on screen, 0..3600 (drawn once)
};

// A moment a film says in words: a caption from `time` on.
struct FilmEvent {
    double time = 0.0;     // simulated s
    std::string caption;   // the words, in the film's language
};

// What a film shows besides the dragon. Text follows the frame's height and never drops below
// kMinTextPx, so a 400 x 300 GIF reads as well as a 1080p film.
struct FilmLook {
    bool clock = true;   // "t = 412.474 s" top right, the playback rate ("\u00d720") under it
    bool legend = true;  // what the colours mean, top left
    bool inset = true;   // the whole dragon small, when the camera follows the head or is zoomed in
    std::vector<FilmEvent> events;  // each captioned from its moment on
    // How long a caption stays, s of film; one whose event is the clip's last moment stays to
    // the end (a held frame).
    double caption_seconds = 3.0;
};

// The captions a film of [from, to] should carry: the head reaching the turning space (on
// the plain spiral, when that lies inside), two benches touching at `to` (`contact`) or else
// the first contact where the range passes it (first_contact_covering; at `from`, "past the
// first contact", when the range starts after it), and the end of the valid motion when `to`
// is it.
// Worded in `language`.
std::vector<FilmEvent> clip_events(const Simulation& sim, double from, double to,
                                   const std::optional<CollisionMark>& contact, Language language = Language::en);
// The caption of a first contact: "first contact: bench 1 touches bench 9, t = 412.473838 s".
std::string contact_caption(const CollisionMark& mark, double time, Language language = Language::en);
// What a film of `s` shows, in words, for its annotation: "Coiling in: pitch 0.55 m, head 1 m/s".
std::string scenario_line(const Scenario& s, Language language = Language::en);

// One view for a stretch of motion, so the picture does not zoom as the dragon coils: it fits
// the dragon at nine moments spread over [from, to] (it coils in or out monotonically, so a
// few spread samples bound it; `margin`, a fraction of the box on every side, covers the rest).
Camera fit_over(const Simulation& sim, double from, double to, double margin = Camera{}.margin);

// The stretch of path a still camera shows over [from, to] (SceneOptions::guide_arcs): every
// frame's own guide_arcs_of at the same nine moments, joined (arc length from .. to, m).
std::pair<double, double> guide_arcs_over(const Simulation& sim, double from, double to);
// One speed range for a stretch, from 257 moments spread over it (speeds peak briefly), so a
// colour means one speed all through.
struct SpeedRange {
    double lo;  // m/s
    double hi;  // m/s, above lo
};
// The range over [from, to], s, within the valid motion (else the InputError Simulation::frame
// throws).
SpeedRange speed_range_over(const Simulation& sim, double from, double to);

// A clip made drawable: the moment and the scene of every frame. Frames are at from,
// from + speedup / fps, ... and the last exactly at `to` (so a collision is the final picture),
// then `hold` seconds more of `to`.
class Animation {
public:
    // Throws InputError for an empty or reversed range ("time range"), a time off the path
    // (past the spiral's centre, say: "time range start", "time range end"), a speedup or fps
    // <= 0 ("speedup", "frame rate"), a hold outside 0..3600 s ("hold"), more than
    // kMaxFilmFrames frames ("film frame count") or a fixed or followed view that cannot be
    // drawn (see check_view). With the camera on fit_dragon the view is fixed for the whole
    // clip: it fits the dragon at nine moments spread over it; with speed colours and no range
    // given, the range is fixed likewise from those moments.
    // `end_mark`: two benches that touch at `to`, drawn marked on the frames of that moment.
    // Keeps a reference to `sim`, which must outlive the animation.
    // `look`: the clock, legend, inset and captions (with the clock on and no annotation
    // given, the annotation names the scenario instead of the time).
    Animation(const Simulation& sim, Clip clip, double fps, SceneOptions scene,
              std::optional<CollisionMark> end_mark = {}, FilmLook look = {});

    int frame_count() const { return frame_count_; }  // held frames included
    // Frames that differ: from this one on, the held last moment repeats frame distinct_frames() - 1.
    int distinct_frames() const { return moving_frames_; }
    double fps() const { return fps_; }           // frames a second of film
    const Clip& clip() const { return clip_; }    // as given
    double time_at(int index) const;              // the simulated moment of frame `index`, s
    Scene scene_at(int index) const;              // what frame `index` shows
    // draw(scene_at(index)) onto a width x height picture.
    void paint(int index, cairo_t* cr, int width, int height) const;

private:
    int frame_of(double t) const;  // the first frame at or after simulated time t

    const Simulation* sim_;
    Clip clip_;
    double fps_;
    SceneOptions scene_;
    std::optional<CollisionMark> end_mark_;
    FilmLook look_;
    int moving_frames_ = 0;
    int frame_count_ = 0;
    // The backdrop (background, turning space, path) drawn once for a still camera, shared by
    // the threads that paint frames (render/backdrop.hpp).
    std::shared_ptr<render::BackdropCache> backdrop_;
};

// A zoomed clip is refused (InputError, Key::zoom, as require_zoom_resolves in dragon/look.hpp)
// when doubles cannot resolve its pixels at width x height: a fixed view is the same on every
// frame, and a followed head is furthest from the origin at an end of the clip (the spiral's
// coil-in starts outermost, the turnaround's coil-out ends outermost).
void require_zoom_resolves(const Animation& anim, int width_px, int height_px, double zoom);


// Renders and encodes the animation at its frame rate (opt.fps is replaced by anim.fps()).
EncodeStats write_video(const Animation& anim, const std::string& path, VideoOptions opt,
                        const ProgressFn& progress = {});

}  // namespace dragon
