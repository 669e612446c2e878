#include "render/paint.hpp"
#include "render/cairo_handles.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <utility>

#include <fmt/format.h>

namespace dragon::render {

Rgba ramp_colour(const std::vector<Rgba>& stops, double t) {
    if (stops.empty()) return {};
    if (stops.size() == 1 || !(t > 0)) return stops.front();
    if (t >= 1) return stops.back();
    const double x = t * static_cast<double>(stops.size() - 1);
    const auto i = static_cast<std::size_t>(x);
    const double f = x - static_cast<double>(i);
    const Rgba& a = stops[i];
    const Rgba& b = stops[std::min(i + 1, stops.size() - 1)];
    return {a.r + f * (b.r - a.r), a.g + f * (b.g - a.g), a.b + f * (b.b - a.b), a.a + f * (b.a - a.a)};
}

namespace {
thread_local std::vector<LayoutItem>* recording = nullptr;
}  // namespace

LayoutRecording::LayoutRecording() { recording = &placed_; }
LayoutRecording::~LayoutRecording() { recording = nullptr; }
bool layout_recording() { return recording != nullptr; }

void log_placed(cairo_t* cr, LayoutItem::Kind kind, double x0, double y0, double x1, double y1, const std::string& what,
                double size) {
    if (!recording) return;
    // The box's corners in device space (the transformation may scale: a PDF page in points).
    double xs[4] = {x0, x1, x0, x1}, ys[4] = {y0, y0, y1, y1};
    LayoutItem p{kind, 1e300, 1e300, -1e300, -1e300, 0, what};
    for (int i = 0; i < 4; ++i) {
        cairo_user_to_device(cr, &xs[i], &ys[i]);
        p.x0 = std::min(p.x0, xs[i]), p.y0 = std::min(p.y0, ys[i]);
        p.x1 = std::max(p.x1, xs[i]), p.y1 = std::max(p.y1, ys[i]);
    }
    double dx = size, dy = 0;
    cairo_user_to_device_distance(cr, &dx, &dy);
    p.size = std::hypot(dx, dy);
    if (kind == LayoutItem::Kind::text) {  // a text the clip cuts (a panel's, a plot's frame)
        double c0 = 0, c1 = 0, c2 = 0, c3 = 0;
        cairo_clip_extents(cr, &c0, &c1, &c2, &c3);
        const double slack = 0.5 * (x1 - x0 > 0 ? 1.0 : 0.0);
        p.clipped = x0 < c0 - slack || y0 < c1 - slack || x1 > c2 + slack || y1 > c3 + slack;
    }
    recording->push_back(std::move(p));
}

}  // namespace dragon::render

void dragon::cairo::log_new_surface(cairo_surface_t* target) {
    if (render::layout_recording() && cairo_surface_get_type(target) == CAIRO_SURFACE_TYPE_IMAGE)
        render::log_picture(cairo_image_surface_get_width(target), cairo_image_surface_get_height(target));
}

namespace dragon::render {

void log_picture(double w, double h, const std::string& what) {
    if (recording) recording->push_back({LayoutItem::Kind::picture, 0, 0, w, h, 0, what});
}

namespace {
// A line of text as the log holds it: from its start to its advance, 0.8 em above the baseline
// (capitals, accents and CJK ideographs) to 0.2 em below it.
void log_text(cairo_t* cr, double x, double baseline, double width, double size_px, const std::string& s) {
    if (recording) log_placed(cr, LayoutItem::Kind::text, x, baseline - 0.8 * size_px, x + width, baseline + 0.2 * size_px, s, size_px);
}

void select_font(cairo_t* cr, const std::string& font, double size_px, bool bold) {
    cairo_select_font_face(cr, font.c_str(), CAIRO_FONT_SLANT_NORMAL,
                           bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, size_px);
}

// The code point starting at s[i] (UTF-8) and its length in bytes. A broken or overlong
// sequence reads as U+FFFD over its first byte alone: Cairo refuses invalid UTF-8 (and its
// context then draws nothing more), and no text can make a loop over it stall.
constexpr char32_t kReplacement = 0xFFFD;
std::pair<char32_t, std::size_t> next_code_point(const std::string& s, std::size_t i) {
    const auto b = static_cast<unsigned char>(s[i]);
    if (b < 0x80) return {b, 1};
    const std::size_t n = (b >> 5) == 0x6 ? 2 : (b >> 4) == 0xE ? 3 : (b >> 3) == 0x1E ? 4 : 0;
    if (n == 0 || i + n > s.size()) return {kReplacement, 1};
    char32_t c = b & (0x7F >> n);
    for (std::size_t k = 1; k < n; ++k) {
        const auto t = static_cast<unsigned char>(s[i + k]);
        if ((t >> 6) != 0x2) return {kReplacement, 1};
        c = (c << 6) | (t & 0x3F);
    }
    const char32_t least[] = {0, 0, 0x80, 0x800, 0x10000};
    if (c < least[n] || c > 0x10FFFF || (c >= 0xD800 && c <= 0xDFFF)) return {kReplacement, 1};
    return {c, n};
}

// The UTF-8 of one code point.
std::string utf8(char32_t c) {
    std::string out;
    if (c < 0x80) {
        out += static_cast<char>(c);
    } else if (c < 0x800) {
        out += static_cast<char>(0xC0 | (c >> 6));
        out += static_cast<char>(0x80 | (c & 0x3F));
    } else if (c < 0x10000) {
        out += static_cast<char>(0xE0 | (c >> 12));
        out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (c & 0x3F));
    } else {
        out += static_cast<char>(0xF0 | (c >> 18));
        out += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
        out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (c & 0x3F));
    }
    return out;
}

// Does the font selected on cr have a glyph for this text (one code point)? Cairo's toy API
// shows a missing glyph as an empty box (glyph 0). Answers are kept per thread: a film asks
// the same few characters on every frame.
bool covers(cairo_t* cr, const std::string& family, bool bold, const std::string& code_point) {
    thread_local std::map<std::pair<std::string, std::string>, bool> known;
    const auto key = std::make_pair(family + (bold ? "\x01" : ""), code_point);
    if (auto it = known.find(key); it != known.end()) return it->second;
    cairo_glyph_t* glyphs = nullptr;
    int count = 0;
    const cairo_status_t st = cairo_scaled_font_text_to_glyphs(cairo_get_scaled_font(cr), 0, 0, code_point.data(),
                                                               static_cast<int>(code_point.size()), &glyphs, &count,
                                                               nullptr, nullptr, nullptr);
    const bool has = st == CAIRO_STATUS_SUCCESS && count > 0 &&
                     std::all_of(glyphs, glyphs + count, [](const cairo_glyph_t& g) { return g.index != 0; });
    cairo_glyph_free(glyphs);
    known.emplace(key, has);
    return has;
}

// A stretch of text set in one font: the theme's, or a fallback for the characters it lacks.
struct Run {
    std::string text;
    const std::string* font;
};

// The text cut into runs by font: each character in the theme's font when it has it, else in
// the first fallback that has it (kFallbackFonts: Chinese, Japanese and Korean glyphs), else
// in the theme's font after all. ASCII is taken as the theme's: every text font has it.
std::vector<Run> font_runs(cairo_t* cr, const std::string& font, double size_px, bool bold, const std::string& s) {
    static const std::vector<std::string> fallbacks(std::begin(kFallbackFonts), std::end(kFallbackFonts));
    std::vector<Run> runs;
    for (std::size_t i = 0; i < s.size();) {
        const auto [c, n] = next_code_point(s, i);
        const std::string one = utf8(c);
        const std::string* chosen = &font;
        if (c >= 0x80) {
            select_font(cr, font, size_px, bold);
            if (!covers(cr, font, bold, one)) {
                for (const std::string& f : fallbacks) {
                    select_font(cr, f, size_px, bold);
                    if (covers(cr, f, bold, one)) {
                        chosen = &f;
                        break;
                    }
                }
            }
        }
        if (runs.empty() || runs.back().font != chosen) runs.push_back({"", chosen});
        runs.back().text += one;
        i += n;
    }
    return runs;
}

// Each run shown (or its outline added to the path) from the current point on: Cairo moves
// the current point to the end of what it set.
void set_runs(cairo_t* cr, const std::vector<Run>& runs, double size_px, bool bold, bool as_path) {
    for (const Run& r : runs) {
        select_font(cr, *r.font, size_px, bold);
        if (as_path) cairo_text_path(cr, r.text.c_str());
        else cairo_show_text(cr, r.text.c_str());
    }
}

double runs_width(cairo_t* cr, const std::vector<Run>& runs, double size_px, bool bold) {
    double w = 0;
    for (const Run& r : runs) {
        select_font(cr, *r.font, size_px, bold);
        cairo_text_extents_t e;
        cairo_text_extents(cr, r.text.c_str(), &e);
        w += e.x_advance;
    }
    return w;
}
}  // namespace

void text(cairo_t* cr, const std::string& font, double size_px, double x, double y,
          const std::string& s, double align, double valign, bool bold) {
    if (s.empty()) return;
    const std::vector<Run> runs = font_runs(cr, font, size_px, bold, s);
    const double width = runs_width(cr, runs, size_px, bold);
    // Cap height of DejaVu Sans is 0.73 em; aligning on it keeps a row of labels level
    // whatever letters they hold.
    const double cap = 0.73 * size_px;
    cairo_move_to(cr, x - align * width, y + valign * cap);
    set_runs(cr, runs, size_px, bold, false);
    log_text(cr, x - align * width, y + valign * cap, width, size_px, s);
    cairo_new_path(cr);
}

void halo_text(cairo_t* cr, const std::string& font, double size_px, double x, double y, const std::string& s,
               const Rgba& colour, const Rgba& halo, double halo_px, double align) {
    if (s.empty()) return;
    const std::vector<Run> runs = font_runs(cr, font, size_px, false, s);
    const double width = runs_width(cr, runs, size_px, false);
    // The halo is the glyphs' outline stroked wide; the text itself is shown as text, so a PDF
    // or SVG keeps it selectable and searchable.
    cairo_move_to(cr, x - align * width, y);
    set_runs(cr, runs, size_px, false, true);
    set_colour(cr, {halo.r, halo.g, halo.b, 0.85});
    cairo_set_line_width(cr, halo_px);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    cairo_stroke(cr);
    set_colour(cr, colour);
    cairo_move_to(cr, x - align * width, y);
    set_runs(cr, runs, size_px, false, false);
    log_text(cr, x - align * width, y, width, size_px, s);
    cairo_new_path(cr);
}

double text_width(cairo_t* cr, const std::string& font, double size_px, const std::string& s, bool bold) {
    return runs_width(cr, font_runs(cr, font, size_px, bold, s), size_px, bold);
}

namespace {
// Characters a line may break before or after without a space: CJK ideographs, kana, hangul
// and their punctuation (Chinese is written without spaces between words).
bool breaks_anywhere(char32_t c) {
    return (c >= 0x2E80 && c <= 0x9FFF) || (c >= 0xAC00 && c <= 0xD7AF) || (c >= 0xF900 && c <= 0xFAFF) ||
           (c >= 0xFF00 && c <= 0xFFEF) || (c >= 0x20000 && c <= 0x3FFFF);
}
// Punctuation that must not start a line (it closes what is before it).
bool closes(char32_t c) {
    static constexpr char32_t no_start[] = {0x3001, 0x3002, 0xFF0C, 0xFF0E, 0xFF1A, 0xFF1B, 0xFF01, 0xFF1F,
                                             0xFF09, 0x3011, 0x300B, 0x300D, 0x300F, 0x201D, 0x2019, 0xFF05};
    return std::find(std::begin(no_start), std::end(no_start), c) != std::end(no_start) || c == ')' || c == ',' ||
           c == '.' || c == ':' || c == ';' || c == '%';
}
// Punctuation that must not end a line (it opens what comes after it).
bool opens(char32_t c) { return c == 0xFF08 || c == 0x3010 || c == 0x300A || c == 0x300C || c == 0x300E || c == 0x201C || c == '('; }

// The pieces a line may be broken between: words at spaces, and single characters of CJK
// text; `spaced` says whether a space stood before the piece.
struct Piece {
    std::string text;
    bool spaced = false;
};
std::vector<Piece> pieces(const std::string& s) {
    std::vector<Piece> out;
    bool space = false;
    char32_t prev = 0;
    for (std::size_t i = 0; i < s.size();) {
        const auto [c, n] = next_code_point(s, i);
        if (c == ' ') {
            space = true;
        } else {
            const bool cut = out.empty() || space ||
                             ((breaks_anywhere(c) || breaks_anywhere(prev)) && !closes(c) && !opens(prev));
            if (cut) out.push_back({"", space && !out.empty()});
            out.back().text += utf8(c);
            space = false;
        }
        prev = c;
        i += n;
    }
    return out;
}

// Pieces joined greedily into lines no wider than `room` (a piece wider than that gets a line
// of its own).
std::vector<std::string> wrap(cairo_t* cr, const std::string& font, double size, const std::string& s, double room,
                              bool bold) {
    std::vector<std::string> lines;
    std::string line;
    for (const Piece& p : pieces(s)) {
        const std::string longer = line.empty() ? p.text : line + (p.spaced ? " " : "") + p.text;
        if (line.empty() || text_width(cr, font, size, longer, bold) <= room) {
            line = longer;
        } else {
            lines.push_back(line);
            line = p.text;
        }
    }
    if (!line.empty()) lines.push_back(line);
    return lines;
}

bool fits(cairo_t* cr, const std::string& font, double size, const std::vector<std::string>& lines, double room,
          bool bold) {
    return std::all_of(lines.begin(), lines.end(),
                       [&](const std::string& l) { return text_width(cr, font, size, l, bold) <= room; });
}
}  // namespace

FittedText fit_text(cairo_t* cr, const std::string& font, double size, const std::string& s, double room, bool bold,
                    int max_lines, bool keep_size) {
    if (s.empty()) return {size, {}};
    if (keep_size) return {size, fits(cr, font, size, {s}, room, bold) ? std::vector<std::string>{s} : wrap(cr, font, size, s, room, bold)};
    // Never under the floor (a 13 px label at kMinTextPx: the smallest text, 11 px at 800 px,
    // at 9.3 px), nor smaller than asked when that is already under it.
    const double least = std::min(size, kMinTextPx * 11.0 / 13.0);
    // One line, down to 88 % of the size: reads better than a second line holding one word.
    for (double k = 1.0; k >= 0.875 && k * size >= least; k -= 0.025)
        if (fits(cr, font, k * size, {s}, room, bold)) return {k * size, {s}};
    // Wrapped, then smaller until every line fits; at the floor, wrapped into as many lines as
    // it takes.
    double k = 1.0;
    std::vector<std::string> lines = wrap(cr, font, size, s, room, bold);
    while (k * 0.95 * size >= least &&
           (static_cast<int>(lines.size()) > max_lines || !fits(cr, font, k * size, lines, room, bold))) {
        k *= 0.95;
        lines = wrap(cr, font, k * size, s, room, bold);
    }
    return {k * size, lines};
}

double nice_floor(double x) {
    const double p = std::pow(10.0, std::floor(std::log10(x)));
    const double m = x / p;
    return (m >= 5 ? 5 : m >= 2 ? 2 : 1) * p;
}

Ticks nice_ticks(double lo, double hi, int target) {
    Ticks t;
    if (!(hi > lo)) hi = lo + 1;
    const double raw = (hi - lo) / std::max(target, 1);
    const double p = std::pow(10.0, std::floor(std::log10(raw)));
    const double m = raw / p;
    t.step = (m < 1.5 ? 1 : m < 3.5 ? 2 : m < 7.5 ? 5 : 10) * p;
    t.decimals = std::max(0, -static_cast<int>(std::floor(std::log10(t.step) + 1e-9)));
    const double first = std::ceil(lo / t.step - 1e-9);
    for (double k = first;; k += 1) {
        const double v = k * t.step;
        if (v > hi + 1e-9 * t.step) break;
        t.values.push_back(std::abs(v) < 1e-12 * t.step ? 0.0 : v);
        if (t.values.size() > 1000) break;
    }
    return t;
}

std::string format_tick(double v, int decimals) {
    std::string s = fmt::format("{:.{}f}", v, decimals);
    if (s.starts_with('-') && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);  // no "-0.0"
    // A proper minus sign reads better than a hyphen.
    if (!s.empty() && s[0] == '-') s = "\u2212" + s.substr(1);
    return s;
}

std::string scale_label(double metres) {
    if (metres >= 1e4) return fmt::format("{:g} km", metres / 1e3);
    if (metres >= 1) return format_tick(metres, 0) + " m";
    if (metres >= 1e-2) return format_tick(metres, 2) + " m";
    if (metres >= 1e-3) return fmt::format("{:g} mm", metres * 1e3);
    if (metres >= 1e-6) return fmt::format("{:g} \u00b5m", metres * 1e6);
    return fmt::format("{:g} nm", metres * 1e9);
}

}  // namespace dragon::render
