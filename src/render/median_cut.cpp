#include "render/median_cut.hpp"

#include <algorithm>
#include <cmath>

namespace dragon::render {

namespace {

int channel(std::uint32_t rgb, int c) { return static_cast<int>((rgb >> (16 - 8 * c)) & 0xffu); }  // 0 r, 1 g, 2 b

double weight_of(const ColourCount& colour, CutWeight w) {
    const double n = static_cast<double>(colour.pixels);
    return w == CutWeight::pixels ? n : std::sqrt(n);
}

struct Box {
    std::size_t begin, end;
    int widest = 0;     // the channel with the largest range (the first, if several)
    int range = 0;      // that range
    double weight = 0;  // the colours' weights summed (exact for pixel counts below 2^53)
    double claim = 0;   // how much splitting it matters: range x weight or range x sqrt(weight)
};

Box describe(const std::vector<ColourCount>& colours, std::size_t begin, std::size_t end, CutWeight w) {
    Box box{begin, end};
    int lo[3] = {255, 255, 255}, hi[3] = {0, 0, 0};
    for (std::size_t i = begin; i < end; ++i) {
        for (int c = 0; c < 3; ++c) {
            lo[c] = std::min(lo[c], channel(colours[i].rgb, c));
            hi[c] = std::max(hi[c], channel(colours[i].rgb, c));
        }
        box.weight += weight_of(colours[i], w);
    }
    for (int c = 0; c < 3; ++c)
        if (hi[c] - lo[c] > box.range) box.range = hi[c] - lo[c], box.widest = c;
    box.claim = w == CutWeight::pixels ? box.range * std::sqrt(box.weight) : box.weight * box.range;
    return box;
}

}  // namespace

std::vector<ColourBox> median_cut(std::vector<ColourCount>& colours, std::size_t max_boxes, CutWeight w,
                                  BoxOrder order) {
    std::vector<Box> boxes;
    if (!colours.empty()) boxes.push_back(describe(colours, 0, colours.size(), w));
    while (boxes.size() < max_boxes) {
        // The first box with the largest claim; one colour alone (no range) has none.
        auto best = boxes.end();
        for (auto it = boxes.begin(); it != boxes.end(); ++it)
            if (it->end - it->begin >= 2 && it->claim > 0 && (best == boxes.end() || it->claim > best->claim)) best = it;
        if (best == boxes.end()) break;
        const Box box = *best;
        const int c = box.widest;
        std::sort(colours.begin() + static_cast<std::ptrdiff_t>(box.begin),
                  colours.begin() + static_cast<std::ptrdiff_t>(box.end),
                  [c](const ColourCount& a, const ColourCount& b) { return channel(a.rgb, c) < channel(b.rgb, c); });
        // At the weighted median, but never leaving a side empty.
        double acc = 0;
        std::size_t cut = box.begin + 1;
        for (std::size_t i = box.begin; i + 1 < box.end; ++i) {
            acc += weight_of(colours[i], w);
            cut = i + 1;
            if (2 * acc >= box.weight) break;
        }
        if (order == BoxOrder::lower_in_place) {
            *best = describe(colours, box.begin, cut, w);
        } else {
            boxes.erase(best);
            boxes.push_back(describe(colours, box.begin, cut, w));
        }
        boxes.push_back(describe(colours, cut, box.end, w));
    }
    std::vector<ColourBox> out;
    for (const Box& b : boxes) out.push_back({b.begin, b.end});
    return out;
}

}  // namespace dragon::render
