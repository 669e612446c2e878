// A picture's size as people write it, "1280x720": one parser for every place that reads one
// (the CLI's --size for render, video and film, a storyboard's [film] size), so they all accept
// and refuse the same texts with the same words. And a picture's size on a page: a width in
// inches and a text size in points, laid out in pixels for PNG, SVG and PDF.
#pragma once

#include <string_view>

namespace dragon {

// A picture's size in pixels, as parse_picture_size reads it.
struct PictureSize {
    int width = 0;   // pixels
    int height = 0;  // pixels
};

// The sides a picture may have. Below 16 px nothing of the dragon, its clock or legend can be
// made out; 16384 px a side is already a 1 GiB image: more is a typo, not a picture.
inline constexpr int kMinPictureSide = 16;
inline constexpr int kMaxPictureSide = 16384;

// "1280x720" (or "1280X720") -> {1280, 720}: digits, x, digits, nothing else. Throws
// InputError with field "picture size", the text as value and what is allowed: the form, or
// each side kMinPictureSide..max_side px. Callers whose output allows less (a video's codecs:
// kMaxVideoSide) pass their own largest side.
PictureSize parse_picture_size(std::string_view text, int max_side = kMaxPictureSide);

// A picture for a page: its width there, the size of its text, and a PNG's pixels per inch.
// The body text (labels, ticks, legends, scale bar) is font_pt; titles, captions and clocks a
// fifth larger; lines and gaps follow the text (a 1 pt line at 8 pt text).
struct PrintSize {
    double width_in = 3.5;  // the picture's width on the page, in
    double font_pt = 8.0;   // the body text's size, pt
    double dpi = 300.0;     // PNG only: PDF and SVG are vector pages of width_in
};
inline constexpr double kMinPrintWidthIn = 1.0;   // in: a stamp
inline constexpr double kMaxPrintWidthIn = 40.0;  // in: a poster
inline constexpr double kMinFontPt = 4.0;         // pt: still readable
inline constexpr double kMaxFontPt = 36.0;        // pt: a headline
inline constexpr double kMinDpi = 72.0;           // a screen
inline constexpr double kMaxDpi = 1200.0;         // a photo print
inline constexpr double kCmPerInch = 2.54;        // cm in an inch

// The named sizes: "column" (3.5 in, 8 pt: one column of a two-column paper), "page" (7 in,
// 9 pt: across both columns), "a4" (16 cm, 10.5 pt: the text width of an A4 page with 2.5 cm
// margins, at the size of Chinese body text, wuhao), each at 300 dpi. Throws InputError (field
// "print size") for any other name.
PrintSize print_preset(std::string_view name);
// Throws InputError naming the first value outside its range above (fields "print width",
// "font size", "dpi").
void check_print_size(const PrintSize& size);

// Where a picture goes on a page: its size in points (PDF, SVG) and the resolution a PNG
// states (its pHYs chunk, which LaTeX and Word read). Zero: 96 px to the inch, none stated.
struct Page {
    double width_pt = 0;   // the page's width, pt (0: the picture's pixels at 96 to the inch)
    double height_pt = 0;  // the page's height, pt
    double dpi = 0;        // a PNG's stated resolution (0: none stated)
};

// A picture of aspect height / width at a print size: drawn on width_px x height_px (96 px to
// the inch on a vector page, size.dpi on a PNG), its body text text_px tall, on `page`.
struct PrintLayout {
    int width_px = 0;    // the pixels drawn across
    int height_px = 0;   // the pixels drawn down
    double text_px = 0;  // the body text's size in those pixels (Scene::text_px)
    Page page;           // where the drawing goes on the page
};
// Throws InputError (check_print_size's, or a sentence when the pixels would exceed max_side
// or either side fall under kMinPictureSide).
PrintLayout print_layout(const PrintSize& size, double aspect, bool raster, int max_side = kMaxPictureSide);

}  // namespace dragon
