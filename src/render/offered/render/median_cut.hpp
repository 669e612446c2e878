// Median cut: a picture's colours split into at most N boxes, each to become one palette entry.
// One algorithm for the gallery's palette PNGs (render/png8.cpp) and the GIF palettes
// (video/palette.cpp); they differ in how a colour weighs and in the order the boxes are kept,
// and each keeps its own by parameters (their pictures stay byte for byte what they were).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace dragon::render {

// One colour of a picture's histogram: where it lies (three channels of up to 8 bits, in
// whatever scale the caller bins them: 0..255, or 0..31 for 5-bit bins) and how many pixels
// have it. The colours passed are distinct.
struct ColourCount {
    std::uint32_t rgb = 0;  // 0x00RRGGBB
    std::uint64_t pixels = 0;
};

// How much a colour counts when choosing the box to split next (its claim: its range along its
// widest channel times its weight) and where to split it (its weighted median along that
// channel).
enum class CutWeight {
    // A colour weighs its pixel count; a box's claim is its range times the square root of its
    // pixels (the palette PNGs: exact colours, most of them anti-aliased blends of a few pixels).
    pixels,
    // A colour weighs the square root of its pixel count, and a box the sum of its colours'
    // (the GIFs' 5-bit bins: a big flat area's say is damped, so a small distinct patch, the
    // head or a marked collision, still counts against thousands of background pixels).
    sqrt_pixels,
};

// Where the halves of a split box go in the list of boxes: the palette's order, and which of
// two boxes with equal claims is split first (the earlier).
enum class BoxOrder {
    lower_in_place,  // the lower half takes the box's place, the upper goes last
    both_last,       // the box leaves the list; its lower half, then its upper, go last
};

// A box: colours[begin, end) after median_cut has reordered them.
struct ColourBox {
    std::size_t begin = 0, end = 0;
};

// Splits the box with the largest claim at its weighted median along its widest channel (never
// leaving a side empty), until there are `max_boxes` boxes or none has two colours. Reorders
// `colours` so that each box is a contiguous range; returns the boxes (none for no colours).
std::vector<ColourBox> median_cut(std::vector<ColourCount>& colours, std::size_t max_boxes, CutWeight weight,
                                  BoxOrder order);

}  // namespace dragon::render
