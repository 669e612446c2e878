#include "video/palette.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace dragon::video {

namespace {

int channel(int bin, int c) { return (bin >> (palette_bits * (2 - c))) & 0x1f; }  // c: 0 r, 1 g, 2 b

// A bin's say in where boxes split: the square root of its pixel count, so a small but
// distinct patch (the head, the tail, a marked collision) wins its own entry against the
// thousands of background and body pixels, while those still get the most entries.
template <class Bin>
double weight(const Bin& b) { return std::sqrt(static_cast<double>(b.count)); }

struct Box {
    std::vector<int> bins;  // non-empty bins inside
    double weight = 0;
    std::uint64_t count = 0;
    int widest = 0;         // channel with the largest range
    int range = 0;          // that range, in bins
};

template <class Hist>
Box make_box(std::vector<int> bins, const Hist& hist) {
    Box box;
    int lo[3] = {31, 31, 31}, hi[3] = {0, 0, 0};
    for (int b : bins) {
        box.count += hist[static_cast<size_t>(b)].count;
        box.weight += weight(hist[static_cast<size_t>(b)]);
        for (int c = 0; c < 3; ++c) {
            lo[c] = std::min(lo[c], channel(b, c));
            hi[c] = std::max(hi[c], channel(b, c));
        }
    }
    for (int c = 0; c < 3; ++c) {
        if (hi[c] - lo[c] > box.range) {
            box.range = hi[c] - lo[c];
            box.widest = c;
        }
    }
    box.bins = std::move(bins);
    return box;
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
    std::vector<int> seen;
    for (int b = 0; b < palette_bins; ++b)
        if (hist_[static_cast<size_t>(b)].count > 0) seen.push_back(b);
    std::vector<Box> boxes;
    if (!seen.empty()) boxes.push_back(make_box(std::move(seen), hist_));

    while (static_cast<int>(boxes.size()) < max_colours) {
        auto best = boxes.end();
        double best_score = 0.0;
        for (auto it = boxes.begin(); it != boxes.end(); ++it) {
            if (it->bins.size() < 2) continue;
            const double score = it->weight * it->range;
            if (score > best_score) {
                best_score = score;
                best = it;
            }
        }
        if (best == boxes.end()) break;
        Box box = std::move(*best);
        boxes.erase(best);
        const int c = box.widest;
        std::sort(box.bins.begin(), box.bins.end(),
                  [c](int a, int b) { return channel(a, c) < channel(b, c); });
        // Split at the weighted median, but never leave a side empty.
        double acc = 0;
        size_t cut = 1;
        for (size_t i = 0; i + 1 < box.bins.size(); ++i) {
            acc += weight(hist_[static_cast<size_t>(box.bins[i])]);
            cut = i + 1;
            if (2 * acc >= box.weight) break;
        }
        std::vector<int> left(box.bins.begin(), box.bins.begin() + static_cast<std::ptrdiff_t>(cut));
        std::vector<int> right(box.bins.begin() + static_cast<std::ptrdiff_t>(cut), box.bins.end());
        boxes.push_back(make_box(std::move(left), hist_));
        boxes.push_back(make_box(std::move(right), hist_));
    }

    Palette pal;
    pal.colours.fill(0xff000000u);
    pal.size = std::max<int>(1, static_cast<int>(boxes.size()));
    std::vector<bool> assigned(palette_bins, false);
    for (size_t i = 0; i < boxes.size(); ++i) {
        std::uint64_t r = 0, g = 0, b = 0;
        for (int bin : boxes[i].bins) {
            const Bin& h = hist_[static_cast<size_t>(bin)];
            r += h.r;
            g += h.g;
            b += h.b;
            pal.lut[static_cast<size_t>(bin)] = static_cast<std::uint8_t>(i);
            assigned[static_cast<size_t>(bin)] = true;
        }
        const std::uint64_t n = boxes[i].count, half = n / 2;
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
