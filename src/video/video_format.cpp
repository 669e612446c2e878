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
constexpr double max_fps = 240.0;
// A frame at most every 100 s: GIF stores a frame's delay in 1/100 s in 16 bits (655 s at
// most), and the MP4 muxer refuses the durations of rates below ~1e-5.
constexpr double min_fps = 0.01;
constexpr int max_side = 8192;  // px; memory and the codecs' limits, not taste
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

void validate(const VideoOptions& opt, VideoFormat format) {
    if (opt.width < 2 || opt.height < 2 || opt.width > max_side || opt.height > max_side)
        throw InputError(fmt::format("video size {}x{} is not allowed: each side must be 2 to {} pixels",
                                     opt.width, opt.height, max_side));
    if (format != VideoFormat::gif && (opt.width % 2 != 0 || opt.height % 2 != 0))
        throw InputError(fmt::format("video size {}x{} is not allowed for {}: yuv420p needs an even width "
                                     "and height", opt.width, opt.height, to_string(format)));
    if (!(opt.fps >= min_fps) || !(opt.fps <= max_fps))
        throw InputError(fmt::format("--fps {} is not allowed: use a rate from {} to {} frames per second", opt.fps,
                                     min_fps, max_fps));
    if (format == VideoFormat::mp4) {
        const long mbs = static_cast<long>((opt.width + 15) / 16) * ((opt.height + 15) / 16);
        if (mbs > h264_max_macroblocks)
            throw InputError(fmt::format("video size {}x{} is not allowed for mp4: H.264 allows at most {} macroblocks "
                                         "of 16x16 pixels a frame (8192x4352, say), this size has {}",
                                         opt.width, opt.height, h264_max_macroblocks, mbs));
    }
    if (opt.crf && format == VideoFormat::gif)
        throw InputError(fmt::format("--crf {} is not allowed for .gif: a GIF has no quality setting (--colours "
                                     "sets its palette)", *opt.crf));
    if (opt.crf && format == VideoFormat::mp4 && (*opt.crf < 0 || *opt.crf > 51))
        throw InputError(fmt::format("--crf {} is not allowed for H.264: use 0 (lossless) to 51", *opt.crf));
    if (opt.crf && format == VideoFormat::webm && (*opt.crf < 0 || *opt.crf > 63))
        throw InputError(fmt::format("--crf {} is not allowed for VP9: use 0 to 63", *opt.crf));
    if (format == VideoFormat::mp4) {
        bool known = false;
        for (auto p : x264_presets) known = known || p == opt.preset;
        if (!known)
            throw InputError(fmt::format("--preset {} is not allowed: use one of ultrafast, superfast, veryfast, "
                                         "faster, fast, medium, slow, slower, veryslow", opt.preset));
        known = false;
        for (auto t : x264_tunes) known = known || t == opt.tune;
        if (!known)
            throw InputError(fmt::format("--tune {} is not allowed: use one of animation, film, stillimage, grain, "
                                         "psnr, ssim, fastdecode, zerolatency or none", opt.tune));
    }
    if (!(opt.keyframe_seconds > 0.0 && opt.keyframe_seconds <= max_keyframe_seconds))
        throw InputError(fmt::format("key frame interval {} s is not allowed: use more than 0, up to {:g} s",
                                     opt.keyframe_seconds, max_keyframe_seconds));
    if (opt.colours < 2 || opt.colours > 256)
        throw InputError(fmt::format("--colours {} is not allowed: a GIF palette has 2 to 256 colours", opt.colours));
    if (opt.threads < 0 || opt.threads > 64)
        throw InputError(fmt::format("--threads {} is not allowed: use 0 (automatic) to 64", opt.threads));
}

}  // namespace dragon
