// Which container and codec a file name asks for, and which options each can take.
#include <array>
#include <cmath>
#include <string_view>

#include <fmt/format.h>

#include "dragon/atomic_file.hpp"
#include "dragon/scenario.hpp"
#include "dragon/video.hpp"

namespace dragon {

namespace {
constexpr std::array<std::string_view, 10> x264_presets = {
    "ultrafast", "superfast", "veryfast", "faster", "fast", "medium", "slow", "slower", "veryslow", "placebo"};
constexpr std::array<std::string_view, 9> x264_tunes = {"none",     "film",     "animation",  "grain",      "stillimage",
                                                        "psnr",     "ssim",     "fastdecode", "zerolatency"};
// H.264's largest level (6.2) allows 139,264 macroblocks of 16x16 pixels in a frame (8192 x 4352,
// say); decoders refuse more, so a bigger MP4 would be a file no player opens.
constexpr long h264_max_macroblocks = 139264;
constexpr double max_keyframe_seconds = 3600.0;
}  // namespace

VideoFormat video_format_for(const std::string& path) {
    const std::string ext = extension_of(path);
    if (ext == ".mp4") return VideoFormat::mp4;
    if (ext == ".webm") return VideoFormat::webm;
    if (ext == ".gif") return VideoFormat::gif;
    throw InputError(fmt::format("output '{}' has extension '{}': videos are .mp4 (H.264), .webm (VP9) or .gif",
                                 path, ext));
}

const char* to_string(VideoFormat f) {
    switch (f) {
        case VideoFormat::mp4: return "mp4";
        case VideoFormat::webm: return "webm";
        case VideoFormat::gif: return "gif";
    }
    return "?";
}

// Each value named in the library's terms, with what is allowed (the CLI words them with its
// flags: cli/error_words.cpp). The quality's field names the codec, whose scale it is.
void validate(const VideoOptions& opt, VideoFormat format) {
    const std::string size = fmt::format("{}x{}", opt.width, opt.height);
    if (opt.width < 2 || opt.height < 2 || opt.width > kMaxVideoSide || opt.height > kMaxVideoSide)
        throw InputError(Key::video_size, size, fmt::format("each side must be 2 to {} pixels", kMaxVideoSide));
    if (format != VideoFormat::gif && (opt.width % 2 != 0 || opt.height % 2 != 0))
        throw InputError(Key::video_size, size,
                         fmt::format("{} frames are yuv420p, which needs an even width and height", to_string(format)));
    if (!(opt.fps >= kMinVideoFps) || !(opt.fps <= kMaxVideoFps))
        throw InputError(Key::fps, error_value(opt.fps),
                         fmt::format("use a rate from {} to {} frames per second", kMinVideoFps, kMaxVideoFps));
    if (format == VideoFormat::webm && static_cast<long>(opt.width) * opt.height > kMaxWebmPixels)
        throw InputError(fmt::format("video size {} is not allowed for webm: a VP9 frame has at most {} pixels "
                                     "(4096x4096, say), this size has {}; its encoder needs ~90 bytes of memory a "
                                     "pixel, over 2 GB past that (use .mp4 for up to 8192x4352)",
                                     size, kMaxWebmPixels, static_cast<long>(opt.width) * opt.height));
    if (format == VideoFormat::mp4) {
        const long mbs = static_cast<long>((opt.width + 15) / 16) * ((opt.height + 15) / 16);
        if (mbs > h264_max_macroblocks)
            throw InputError(fmt::format("video size {} is not allowed for mp4: H.264 allows at most {} macroblocks "
                                         "of 16x16 pixels a frame (8192x4352, say), this size has {}",
                                         size, h264_max_macroblocks, mbs));
    }
    if (opt.crf && format == VideoFormat::gif)
        throw InputError(Key::crf_gif, std::to_string(*opt.crf),
                         "a GIF has no quality setting (VideoOptions::colours sets its palette)");
    if (opt.crf && format == VideoFormat::mp4 && (*opt.crf < 0 || *opt.crf > 51))
        throw InputError(Key::crf_h264, std::to_string(*opt.crf), "use 0 (lossless) to 51");
    if (opt.crf && format == VideoFormat::webm && (*opt.crf < 0 || *opt.crf > 63))
        throw InputError(Key::crf_vp9, std::to_string(*opt.crf), "use 0 to 63");
    if (format == VideoFormat::mp4) {
        bool known = false;
        for (auto p : x264_presets) known = known || p == opt.preset;
        if (!known)
            throw InputError(Key::preset, opt.preset, "use one of ultrafast, superfast, veryfast, faster, fast, "
                                                           "medium, slow, slower, veryslow");
        known = false;
        for (auto t : x264_tunes) known = known || t == opt.tune;
        if (!known)
            throw InputError(Key::tune, opt.tune, "use one of animation, film, stillimage, grain, psnr, ssim, "
                                                       "fastdecode, zerolatency or none");
    }
    if (!(opt.keyframe_seconds > 0.0 && opt.keyframe_seconds <= max_keyframe_seconds))
        throw InputError(Key::keyint, fmt::format("{} s", opt.keyframe_seconds),
                         fmt::format("use more than 0, up to {:g} s", max_keyframe_seconds));
    if (opt.colours < 2 || opt.colours > 256)
        throw InputError(Key::colours, std::to_string(opt.colours), "a GIF palette has 2 to 256 colours");
    if (opt.threads < 0 || opt.threads > 64)
        throw InputError(Key::threads, std::to_string(opt.threads), "use 0 (automatic) to 64");
}

VideoOptions encoder_options(const EncoderRequest& request, VideoFormat format) {
    const std::string ext = std::string(".") + to_string(format);
    if (format != VideoFormat::mp4 && request.preset)
        throw InputError(Key::preset, *request.preset, fmt::format("a preset is libx264's, for .mp4, not {}", ext));
    if (format != VideoFormat::mp4 && request.tune)
        throw InputError(Key::tune, *request.tune, fmt::format("a tune is libx264's, for .mp4, not {}", ext));
    if (format != VideoFormat::gif && request.colours)
        throw InputError(Key::colours, std::to_string(*request.colours),
                         fmt::format("it sets a GIF's palette, for .gif, not {}", ext));
    VideoOptions vo;
    vo.width = request.width;
    vo.height = request.height;
    vo.fps = request.fps;
    vo.crf = request.crf;
    if (request.preset) vo.preset = *request.preset;
    if (request.tune) vo.tune = *request.tune;
    if (request.threads) vo.threads = *request.threads;
    vo.colours = request.colours.value_or(request.speed_colours ? kSpeedColoursPalette : vo.colours);
    validate(vo, format);
    return vo;
}

}  // namespace dragon
