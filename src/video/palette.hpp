// A 256-colour palette for GIF frames, built by median cut over sample pictures, and the
// mapping of ARGB32 pixels onto it.
//
// Our drawings are flat theme colours plus their anti-aliased blends, so a palette fitted to a
// few frames covers every frame, and mapping each pixel to its entry (no dithering) keeps flat
// areas flat: no crawling noise between frames, and small files.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace dragon::video {

// Colours are binned at 5 bits per channel.
inline constexpr int palette_bits = 5;
inline constexpr int palette_bins = 1 << (3 * palette_bits);
inline int bin_of(std::uint32_t argb) {
    const std::uint32_t r = (argb >> 16) & 0xffu, g = (argb >> 8) & 0xffu, b = argb & 0xffu;
    return static_cast<int>(((r >> 3) << 10) | ((g >> 3) << 5) | (b >> 3));
}

class Palette {
public:
    // The palette as AVFrame's PAL8 plane wants it: 256 native-endian 0xAARRGGBB words (unused
    // entries opaque black).
    std::array<std::uint32_t, 256> colours{};
    int size = 0;
    std::vector<std::uint8_t> lut = std::vector<std::uint8_t>(palette_bins);  // bin -> index

    std::uint8_t index_of(std::uint32_t argb) const { return lut[static_cast<std::size_t>(bin_of(argb))]; }
    void map(const std::uint8_t* argb32, int width, int height, int stride, std::uint8_t* out,
             int out_stride) const;
};

class PaletteBuilder {
public:
    // Counts the colours of an opaque ARGB32 picture (rows `stride` bytes apart).
    void add(const std::uint8_t* argb32, int width, int height, int stride);
    bool empty() const { return pixels_ == 0; }
    // Median cut (render/median_cut.hpp): the box with the largest weight times its widest
    // channel range is split at its weighted median along that channel, until there are
    // `max_colours` boxes or none can be split. A bin weighs the square root of its pixel count,
    // so small distinct patches (head, tail, a collision's mark) keep their own colours. Each
    // entry is its box's mean colour (a flat colour alone in its bin comes back exactly). Seen
    // bins map to their box; unseen ones to the entry nearest their centre.
    Palette build(int max_colours = 256) const;

private:
    struct Bin {
        std::uint64_t count = 0, r = 0, g = 0, b = 0;
    };
    std::vector<Bin> hist_ = std::vector<Bin>(palette_bins);
    std::uint64_t pixels_ = 0;
};

}  // namespace dragon::video
