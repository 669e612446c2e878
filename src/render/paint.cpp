#include "render/paint.hpp"

#include <algorithm>
#include <cmath>

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
void select_font(cairo_t* cr, const std::string& font, double size_px, bool bold) {
    cairo_select_font_face(cr, font.c_str(), CAIRO_FONT_SLANT_NORMAL,
                           bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, size_px);
}
}  // namespace

void text(cairo_t* cr, const std::string& font, double size_px, double x, double y,
          const std::string& s, double align, double valign, bool bold) {
    if (s.empty()) return;
    select_font(cr, font, size_px, bold);
    cairo_text_extents_t e;
    cairo_text_extents(cr, s.c_str(), &e);
    // Cap height of DejaVu Sans is 0.73 em; aligning on it keeps a row of labels level
    // whatever letters they hold.
    const double cap = 0.73 * size_px;
    cairo_move_to(cr, x - align * e.x_advance, y + valign * cap);
    cairo_show_text(cr, s.c_str());
    cairo_new_path(cr);
}

void halo_text(cairo_t* cr, const std::string& font, double size_px, double x, double y, const std::string& s,
               const Rgba& colour, const Rgba& halo, double halo_px, double align) {
    if (s.empty()) return;
    select_font(cr, font, size_px, false);
    cairo_text_extents_t e;
    cairo_text_extents(cr, s.c_str(), &e);
    // The halo is the glyphs' outline stroked wide; the text itself is shown as text, so a PDF
    // or SVG keeps it selectable and searchable.
    cairo_move_to(cr, x - align * e.x_advance, y);
    cairo_text_path(cr, s.c_str());
    set_colour(cr, {halo.r, halo.g, halo.b, 0.85});
    cairo_set_line_width(cr, halo_px);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    cairo_stroke(cr);
    set_colour(cr, colour);
    cairo_move_to(cr, x - align * e.x_advance, y);
    cairo_show_text(cr, s.c_str());
    cairo_new_path(cr);
}

double text_width(cairo_t* cr, const std::string& font, double size_px, const std::string& s, bool bold) {
    select_font(cr, font, size_px, bold);
    cairo_text_extents_t e;
    cairo_text_extents(cr, s.c_str(), &e);
    return e.x_advance;
}

namespace {
// Words joined greedily into lines no wider than `room` (a word wider than that gets a line
// of its own).
std::vector<std::string> wrap(cairo_t* cr, const std::string& font, double size, const std::string& s, double room,
                              bool bold) {
    std::vector<std::string> lines;
    std::string line;
    for (std::size_t at = 0; at < s.size();) {
        const std::size_t space = s.find(' ', at);
        const std::string word = s.substr(at, space == std::string::npos ? std::string::npos : space - at);
        at = space == std::string::npos ? s.size() : space + 1;
        if (word.empty()) continue;
        const std::string longer = line.empty() ? word : line + " " + word;
        if (line.empty() || text_width(cr, font, size, longer, bold) <= room) {
            line = longer;
        } else {
            lines.push_back(line);
            line = word;
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
                    int max_lines) {
    if (s.empty()) return {size, {}};
    // One line, down to 88 % of the size: reads better than a second line holding one word.
    for (double k = 1.0; k >= 0.875; k -= 0.025)
        if (fits(cr, font, k * size, {s}, room, bold)) return {k * size, {s}};
    // Wrapped, then smaller until every line fits (a fifth of the size at the least).
    double k = 1.0;
    std::vector<std::string> lines = wrap(cr, font, size, s, room, bold);
    while (k > 0.2 && (static_cast<int>(lines.size()) > max_lines || !fits(cr, font, k * size, lines, room, bold))) {
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
