// Test helper: decode a video back with libavformat and libavcodec, the way a player would.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace dragon::test {

struct Rgb {
    int width = 0, height = 0;
    std::vector<std::uint8_t> pixels;  // RGB24, tightly packed
};

struct DecodedVideo {
    std::string codec;      // libavcodec's decoder name, e.g. "h264"
    std::string container;  // the demuxer's name, e.g. "mov,mp4,m4a,3gp,3g2,mj2"
    int width = 0, height = 0;
    int frames = 0;
    double duration = 0.0;  // s, as the container reports it
    double fps = 0.0;       // the stream's average frame rate
    Rgb kept;               // the frame asked for, as RGB24 (empty if none)
};

// Decodes every frame; keeps frame `keep` (0-based display order) as RGB. Throws on any error.
DecodedVideo decode_video(const std::string& path, int keep = -1);

// An opaque Cairo ARGB32 picture (rows `stride` bytes apart) as RGB24.
Rgb rgb_from_argb32(const std::uint8_t* argb, int width, int height, int stride);

// Peak signal-to-noise ratio over all channels, dB (infinity when equal).
double psnr(const Rgb& a, const Rgb& b);

}  // namespace dragon::test
