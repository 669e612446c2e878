#include "dragon/picture_size.hpp"

#include <algorithm>
#include <cmath>
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
    if (w < 0 || h < 0) throw InputError(Key::size, std::string(text), "use WIDTHxHEIGHT in pixels, e.g. 1280x720");
    if (w < kMinPictureSide || h < kMinPictureSide || w > max_side || h > max_side)
        throw InputError(Key::size, std::string(text),
                         fmt::format("each side must be {}..{} px", kMinPictureSide, max_side));
    return {static_cast<int>(w), static_cast<int>(h)};
}

PrintSize print_preset(std::string_view name) {
    if (name == "column") return {3.5, 8.0, 300.0};
    if (name == "page") return {7.0, 9.0, 300.0};
    if (name == "a4") return {16.0 / kCmPerInch, 10.5, 300.0};
    throw InputError(Key::print, std::string(name), "use column (3.5 in, 8 pt), page (7 in, 9 pt) or a4 (16 cm, 10.5 pt)");
}

void check_print_size(const PrintSize& s) {
    if (!(s.width_in >= kMinPrintWidthIn && s.width_in <= kMaxPrintWidthIn))
        throw InputError(Key::width_in, error_value(s.width_in),
                         fmt::format("give inches, {:g}..{:g} ({:g}..{:g} cm)", kMinPrintWidthIn, kMaxPrintWidthIn,
                                     kMinPrintWidthIn * kCmPerInch, kMaxPrintWidthIn * kCmPerInch));
    if (!(s.font_pt >= kMinFontPt && s.font_pt <= kMaxFontPt))
        throw InputError(Key::font_pt, error_value(s.font_pt),
                         fmt::format("give points, {:g}..{:g}", kMinFontPt, kMaxFontPt));
    if (!(s.dpi >= kMinDpi && s.dpi <= kMaxDpi))
        throw InputError(Key::dpi, error_value(s.dpi), fmt::format("give pixels per inch, {:g}..{:g}", kMinDpi, kMaxDpi));
}

PrintLayout print_layout(const PrintSize& size, double aspect, bool raster, int max_side) {
    check_print_size(size);
    constexpr double css_px_per_in = 96.0, pt_per_in = 72.0;
    const double px_per_in = raster ? size.dpi : css_px_per_in;
    const double w = size.width_in * px_per_in, h = w * aspect;
    if (!(w <= max_side && h <= max_side && std::round(w) >= kMinPictureSide && std::round(h) >= kMinPictureSide))
        throw InputError(fmt::format("a print size of {:g} x {:g} in at {:g} px per inch would be {:.0f} x {:.0f} px: "
                                     "each side must be {}..{} px; use a lower resolution or a smaller width",
                                     size.width_in, size.width_in * aspect, px_per_in, w, h, kMinPictureSide, max_side));
    // One scale on both axes, from the exact width: the page is as wide as asked, as tall as the
    // whole pixels drawn, and the text the size asked in points.
    PrintLayout out;
    out.width_px = static_cast<int>(std::round(w));
    out.height_px = static_cast<int>(std::round(h));
    const double pt_per_px = size.width_in * pt_per_in / out.width_px;
    out.text_px = size.font_pt / pt_per_px;
    out.page = {size.width_in * pt_per_in, out.height_px * pt_per_px, raster ? size.dpi : 0.0};
    return out;
}

}  // namespace dragon
