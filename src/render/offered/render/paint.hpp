// Small Cairo helpers shared by the scene renderer and the plots: colours, text, nice numbers.
#pragma once

#include <string>
#include <vector>

#include <cairo.h>

#include "dragon/render.hpp"

namespace dragon::render {

inline void set_colour(cairo_t* cr, const Rgba& c) { cairo_set_source_rgba(cr, c.r, c.g, c.b, c.a); }

// The colour at t in [0, 1] along evenly spaced stops (clamped), linear in sRGB.
Rgba ramp_colour(const std::vector<Rgba>& stops, double t);

// Fonts for the characters the theme's font lacks, tried in order: Chinese first (the contest's
// language; fonts-noto-cjk, installed by scripts/install-deps.sh), then others that Debian ships.
inline constexpr const char* kFallbackFonts[] = {"Noto Sans CJK SC", "WenQuanYi Micro Hei", "Noto Sans CJK JP",
                                                 "Droid Sans Fallback"};

// Text with Cairo's toy API (DejaVu Sans by default; each character the font lacks in the first
// of kFallbackFonts that has it): `align` 0 = left, 0.5 = centre, 1 = right
// of x; `valign` 0 = baseline at y, 0.5 = middle of the capitals at y, 1 = capitals' top at y.
void text(cairo_t* cr, const std::string& font, double size_px, double x, double y,
          const std::string& s, double align = 0.0, double valign = 0.0, bool bold = false);
// Text with a halo: its outline stroked `halo_px` wide in `halo`, then filled in `colour`.
void halo_text(cairo_t* cr, const std::string& font, double size_px, double x, double y, const std::string& s,
               const Rgba& colour, const Rgba& halo, double halo_px, double align = 0.0);
double text_width(cairo_t* cr, const std::string& font, double size_px, const std::string& s,
                  bool bold = false);

// Text set to fit `room` px across: on one line at `size` if it fits, or a little smaller;
// else wrapped at spaces (and between the characters of Chinese text) into at most `max_lines` lines, smaller still if need be. Measured,
// not scaled: hinting rounds every glyph's advance, so a width does not shrink in proportion
// to the size.
struct FittedText {
    double size = 0.0;
    std::vector<std::string> lines;
};
// `keep_size` (a picture at a print size, whose text must stay the size asked): never smaller,
// wrapped into as many lines as it takes.
FittedText fit_text(cairo_t* cr, const std::string& font, double size_px, const std::string& s, double room,
                    bool bold = false, int max_lines = 2, bool keep_size = false);

// The size of a text set at `nominal` px in an 800 px picture whose text unit is `unit` px:
// nominal * unit on screen; at a print size (body_px > 0) the body size for labels, ticks and
// legends (nominal 14 px and under), a fifth larger for titles, captions and clocks.
inline double text_size(double nominal, double unit, double body_px) {
    return body_px > 0 ? body_px * (nominal > 14 ? 1.2 : 1.0) : nominal * unit;
}

// The layout log: what the renderer placed on a picture, in the picture's device units (a PNG's
// or a frame's pixels, a PDF's points), for a check that reads the layout rather than pixels
// (tests/render/test_layout.cpp): no text off the page, none over another, a legend clear of the
// marks it explains, no text under the floor. Off (and free) unless a LayoutRecording is alive
// on the thread that draws.
struct LayoutItem {
    enum class Kind {
        picture,  // a new picture: its page (every entry up to the next picture is on it)
        text,     // one line of text: its box and its size
        legend,   // a legend's box
        mark,     // something a legend explains and nothing may cover: a touching bench, a contact
    };
    Kind kind = Kind::text;
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // the box, device units
    double size = 0;                         // text: its size (em), device units
    std::string text;                        // text: what it says; legend, mark: what it is
    bool clipped = false;                    // text: part of it lies outside the clip it is drawn in
};
// Records every placement drawn on this thread while alive (one at a time per thread).
class LayoutRecording {
public:
    LayoutRecording();
    ~LayoutRecording();
    LayoutRecording(const LayoutRecording&) = delete;
    LayoutRecording& operator=(const LayoutRecording&) = delete;
    const std::vector<LayoutItem>& placed() const { return placed_; }
    void clear() { placed_.clear(); }

private:
    std::vector<LayoutItem> placed_;
};
// Whether a LayoutRecording is alive on this thread.
bool layout_recording();
// A placement in cr's user space, recorded (in device units) when recording; a no-op otherwise.
void log_placed(cairo_t* cr, LayoutItem::Kind kind, double x0, double y0, double x1, double y1, const std::string& what = {},
                double size = 0);
// A new picture of w x h device units (its page), when recording.
void log_picture(double w, double h, const std::string& what = {});

// Tick positions for [lo, hi]: about `target` steps of 1, 2 or 5 times a power of ten.
struct Ticks {
    double step = 1.0;
    std::vector<double> values;
    int decimals = 0;  // enough to tell neighbouring ticks apart
};
Ticks nice_ticks(double lo, double hi, int target = 5);
// The largest 1, 2 or 5 times a power of ten not above x (> 0).
double nice_floor(double x);
std::string format_tick(double v, int decimals);
// A scale bar's length (1, 2 or 5 times a power of ten, m) in the unit that reads best:
// "0.50 m", "2 m", "5 mm", "200 µm", "20 km".
std::string scale_label(double metres);

}  // namespace dragon::render
