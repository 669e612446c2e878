#include "dragon/picture_size.hpp"

#include <algorithm>
#include <string>

#include <fmt/format.h>

#include "dragon/errors.hpp"

namespace dragon {

namespace {

// The digits of text[from, to) as a number, or -1 if there are none or anything else is there.
// Saturates far above any side allowed, so "99999999999x5" reads as too large, not as garbage.
long digits(std::string_view text, std::size_t from, std::size_t to) {
    if (to <= from) return -1;
    constexpr long saturated = 1'000'000'000;
    long v = 0;
    for (std::size_t i = from; i < to; ++i) {
        if (text[i] < '0' || text[i] > '9') return -1;
        v = std::min(saturated, 10 * v + (text[i] - '0'));
    }
    return v;
}

}  // namespace

PictureSize parse_picture_size(std::string_view text, int max_side) {
    const std::size_t x = text.find_first_of("xX");
    const long w = x == std::string_view::npos ? -1 : digits(text, 0, x);
    const long h = x == std::string_view::npos ? -1 : digits(text, x + 1, text.size());
    if (w < 0 || h < 0) throw InputError("picture size", std::string(text), "use WIDTHxHEIGHT in pixels, e.g. 1280x720");
    if (w < kMinPictureSide || h < kMinPictureSide || w > max_side || h > max_side)
        throw InputError("picture size", std::string(text),
                         fmt::format("each side must be {}..{} px", kMinPictureSide, max_side));
    return {static_cast<int>(w), static_cast<int>(h)};
}

}  // namespace dragon
