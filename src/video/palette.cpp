#include "palette.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "render/median_cut.hpp"

namespace dragon::video {

namespace {

int channel(int bin, int c) { return (bin >> (palette_bits * (2 - c))) & 0x1f; }  // c: 0 r, 1 g, 2 b

// A bin as median cut sees it: its 5-bit channels as the colour, its pixels, and back.
render::ColourCount colour_of(int bin, std::uint64_t pixels) {
    return {static_cast<std::uint32_t>(channel(bin, 0) << 16 | channel(bin, 1) << 8 | channel(bin, 2)), pixels};
}
int bin_of_colour(std::uint32_t rgb) {
    return static_cast<int>(((rgb >> 16) & 0x1fu) << (2 * palette_bits) | ((rgb >> 8) & 0x1fu) << palette_bits |
                            (rgb & 0x1fu));
}

}  // namespace

void PaletteBuilder::add(const std::uint8_t* argb32, int width, int height, int stride) {
    for (int y = 0; y < height; ++y) {
        const auto* row = reinterpret_cast<const std::uint32_t*>(argb32 + static_cast<std::ptrdiff_t>(y) * stride);
        for (int x = 0; x < width; ++x) {
            const std::uint32_t p = row[x];
            Bin& bin = hist_[static_cast<size_t>(bin_of(p))];
            ++bin.count;
            bin.r += (p >> 16) & 0xffu;
            bin.g += (p >> 8) & 0xffu;
            bin.b += p & 0xffu;
        }
    }
    pixels_ += static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height);
}

Palette PaletteBuilder::build(int max_colours) const {
    // Median cut on the seen bins (render/median_cut.hpp). A bin's say in where boxes split is
    // the square root of its pixel count, so a small but distinct patch (the head, the tail, a
    // marked collision) wins its own entry against the thousands of background and body pixels,
    // while those still get the most entries.
    std::vector<render::ColourCount> colours;
    for (int b = 0; b < palette_bins; ++b)
        if (hist_[static_cast<size_t>(b)].count > 0) colours.push_back(colour_of(b, hist_[static_cast<size_t>(b)].count));
    const std::vector<render::ColourBox> boxes =
        render::median_cut(colours, static_cast<std::size_t>(std::max(max_colours, 0)), render::CutWeight::sqrt_pixels,
                           render::BoxOrder::both_last);

    Palette pal;
    pal.colours.fill(0xff000000u);
    pal.size = std::max<int>(1, static_cast<int>(boxes.size()));
    std::vector<bool> assigned(palette_bins, false);
    for (size_t i = 0; i < boxes.size(); ++i) {
        std::uint64_t r = 0, g = 0, b = 0, n = 0;
        for (std::size_t k = boxes[i].begin; k < boxes[i].end; ++k) {
            const int bin = bin_of_colour(colours[k].rgb);
            const Bin& h = hist_[static_cast<size_t>(bin)];
            n += h.count;
            r += h.r;
            g += h.g;
            b += h.b;
            pal.lut[static_cast<size_t>(bin)] = static_cast<std::uint8_t>(i);
            assigned[static_cast<size_t>(bin)] = true;
        }
        const std::uint64_t half = n / 2;
        pal.colours[i] = 0xff000000u | static_cast<std::uint32_t>(((r + half) / n) << 16) |
                         static_cast<std::uint32_t>(((g + half) / n) << 8) |
                         static_cast<std::uint32_t>((b + half) / n);
    }
    // Colours the samples never showed: the nearest entry to the bin's centre.
    for (int bin = 0; bin < palette_bins; ++bin) {
        if (assigned[static_cast<size_t>(bin)]) continue;
        const int centre[3] = {channel(bin, 0) * 8 + 4, channel(bin, 1) * 8 + 4, channel(bin, 2) * 8 + 4};
        int best = 0;
        long best_d = std::numeric_limits<long>::max();
        for (int i = 0; i < pal.size; ++i) {
            const std::uint32_t p = pal.colours[static_cast<size_t>(i)];
            const long dr = static_cast<long>((p >> 16) & 0xffu) - centre[0];
            const long dg = static_cast<long>((p >> 8) & 0xffu) - centre[1];
            const long db = static_cast<long>(p & 0xffu) - centre[2];
            const long d = dr * dr + dg * dg + db * db;
            if (d < best_d) {
                best_d = d;
                best = i;
            }
        }
        pal.lut[static_cast<size_t>(bin)] = static_cast<std::uint8_t>(best);
    }
    return pal;
}

void Palette::map(const std::uint8_t* argb32, int width, int height, int stride, std::uint8_t* out,
                  int out_stride) const {
    for (int y = 0; y < height; ++y) {
        const auto* row = reinterpret_cast<const std::uint32_t*>(argb32 + static_cast<std::ptrdiff_t>(y) * stride);
        std::uint8_t* dst = out + static_cast<std::ptrdiff_t>(y) * out_stride;
        for (int x = 0; x < width; ++x) dst[x] = index_of(row[x]);
    }
}

}  // namespace dragon::video
