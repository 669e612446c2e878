// The text furniture: annotation (top left), legend (below it), clock (top right), captions
// (bottom centre). Sizes follow the picture (Units) so a 400 x 300 GIF and a 4K frame read alike.
#include "furniture.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "render/paint.hpp"
#include "render/words.hpp"

namespace dragon::render {

Units Units::of(double w, double h, double body_px) {
    if (body_px > 0) return {w, h, body_px / 12.0, body_px / 12.0, body_px};
    // Sizes are given for an 800 px picture and scale with the shorter side, so a 4K frame
    // looks like a large 800 px one rather than a thin sketch.
    const double u = std::max(0.25, std::min(w, h) / 800.0);
    return {w, h, u, std::max(u, kMinTextPx / 13.0), 0.0};
}

void backdrop(cairo_t* cr, const Theme& theme, double x, double y, double w, double h, double opacity) {
    Rgba bg = theme.background;
    bg.a = opacity;
    set_colour(cr, bg);
    cairo_rectangle(cr, x, y, w, h);
    cairo_fill(cr);
}

namespace {

// The annotation's lines: one per '\n', the first the headline, the rest a little smaller,
// each fitted to the picture's width (wrapped or set smaller rather than run off its edge).
std::vector<FittedText> annotation_blocks(cairo_t* cr, const Scene& s, const Units& un, double right) {
    std::vector<FittedText> blocks;
    const double room = std::max(right - 8 * un.u - 16 * un.ut - 6 * un.u, 0.25 * un.w);
    for (std::size_t at = 0;;) {
        const std::size_t nl = s.annotation.find('\n', at);
        const std::string line = s.annotation.substr(at, nl == std::string::npos ? std::string::npos : nl - at);
        blocks.push_back(fit_text(cr, s.theme.font, un.text(blocks.empty() ? 15 : 13), line, room, false, 2, un.body_px > 0));
        if (nl == std::string::npos) break;
        at = nl + 1;
    }
    return blocks;
}

double gap(const Units& un) { return 6 * un.ut; }

}  // namespace

double annotation_height(cairo_t* cr, const Scene& s, const Units& un, double right) {
    if (!s.show_text || s.annotation.empty()) return 0.0;
    double th = -gap(un);
    for (const auto& b : annotation_blocks(cr, s, un, right)) th += static_cast<double>(b.lines.size()) * (b.size + gap(un));
    return 8 * un.u + th + 14 * un.ut;
}

Box draw_annotation(cairo_t* cr, const Scene& s, const Units& un, double right, double top) {
    if (!s.show_text || s.annotation.empty()) return {{0, top}, {0, top}};
    const std::vector<FittedText> blocks = annotation_blocks(cr, s, un, right);
    double tw = 0;
    for (const auto& b : blocks)
        for (const auto& line : b.lines) tw = std::max(tw, text_width(cr, s.theme.font, b.size, line));
    const double bottom = top + annotation_height(cr, s, un, right);
    backdrop(cr, s.theme, 8 * un.u, top + 8 * un.u, tw + 16 * un.ut, bottom - top - 8 * un.u);
    set_colour(cr, s.theme.text);
    double y = top + 8 * un.u + 7 * un.ut;
    for (const auto& b : blocks)
        for (const auto& line : b.lines) {
            text(cr, s.theme.font, b.size, 8 * un.u + 8 * un.ut, y + 0.5 * b.size, line, 0.0, 0.5);
            y += b.size + gap(un);
        }
    return {{8 * un.u, top + 8 * un.u}, {8 * un.u + tw + 16 * un.ut, bottom}};
}

namespace {

enum class Swatch { bench, outlined, line, dashed, ramp };
struct Entry {
    Swatch kind;
    Rgba colour;
    std::string label;
};

bool same(const Rgba& a, const Rgba& b) { return a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a; }

// What the picture's colours mean, in the order the eye meets them.
std::vector<Entry> legend_entries(const Scene& s) {
    const Theme& t = s.theme;
    const Words& w = words(s.language);
    std::vector<Entry> e;
    if (s.colour_by_speed) {
        e.push_back({Swatch::outlined, t.head, w.head_outlined});
        e.push_back({Swatch::ramp, {}, w.benches_by_speed});
    } else {
        e.push_back({Swatch::bench, t.head, w.head_bench});
        e.push_back({Swatch::bench, t.body, w.body});
        e.push_back({Swatch::bench, t.tail, w.tail});
    }
    if (s.legend_touching) e.push_back({Swatch::bench, t.collision, w.touching});
    bool in = false, curve = false, out = false;
    for (const auto& g : s.guides) {
        in = in || same(g.colour, t.guide);
        curve = curve || same(g.colour, t.s_curve);
        out = out || same(g.colour, t.guide_out);
    }
    if (in) e.push_back({Swatch::line, t.guide, curve || out ? w.path_in : w.path});
    if (curve) e.push_back({Swatch::line, t.s_curve, w.s_curve});
    if (out) e.push_back({Swatch::line, t.guide_out, w.path_out});
    if (s.turning_radius) e.push_back({Swatch::dashed, t.turning_space, w.turning_space});
    return e;
}

void draw_swatch(cairo_t* cr, const Scene& s, const Entry& e, double x, double y, double w, double h, double u) {
    switch (e.kind) {
    case Swatch::bench:
    case Swatch::outlined:
    case Swatch::ramp: {
        cairo_rectangle(cr, x, y, w, h);
        if (e.kind == Swatch::ramp) {
            cairo_pattern_t* grad = cairo_pattern_create_linear(x, 0, x + w, 0);
            const auto& stops = s.theme.speed_ramp;
            for (std::size_t i = 0; i < stops.size(); ++i)
                cairo_pattern_add_color_stop_rgb(grad, stops.size() > 1 ? double(i) / double(stops.size() - 1) : 0.0,
                                                  stops[i].r, stops[i].g, stops[i].b);
            cairo_set_source(cr, grad);
            cairo_pattern_destroy(grad);
        } else {
            set_colour(cr, e.kind == Swatch::outlined ? ramp_colour(s.theme.speed_ramp, 0.5) : e.colour);
        }
        cairo_fill_preserve(cr);
        set_colour(cr, e.kind == Swatch::outlined ? e.colour : s.theme.outline);
        cairo_set_line_width(cr, e.kind == Swatch::outlined ? 2 * u : u);
        cairo_stroke(cr);
        return;
    }
    case Swatch::line:
    case Swatch::dashed: {
        set_colour(cr, e.colour);
        cairo_set_line_width(cr, 1.5 * u);
        const double d[2] = {4 * u, 3 * u};
        if (e.kind == Swatch::dashed) cairo_set_dash(cr, d, 2, 0);
        cairo_move_to(cr, x, y + 0.5 * h);
        cairo_line_to(cr, x + w, y + 0.5 * h);
        cairo_stroke(cr);
        cairo_set_dash(cr, nullptr, 0, 0);
        return;
    }
    }
}

}  // namespace

namespace {
// The legend's box below `top`, px; an empty box when it is left out: on a picture too small
// for a legend at a readable size (a 320 x 180 GIF) it would hide the drawing it explains.
Box legend_box(cairo_t* cr, const Scene& s, const Units& un, double top) {
    if (!s.legend || !s.show_text) return {{0, top}, {0, top}};
    const std::vector<Entry> entries = legend_entries(s);
    const double size = un.text(12), row = 1.5 * size, sw = 1.6 * size, pad = 8 * un.ut;
    double tw = 0;
    for (const auto& e : entries) tw = std::max(tw, text_width(cr, s.theme.font, size, e.label));
    const double x = 8 * un.u, y = top + 6 * un.u;
    const double bw = pad + sw + 0.6 * size + tw + pad, bh = pad + row * static_cast<double>(entries.size()) - (row - size) + pad;
    if (bh > 0.45 * un.h || bw > 0.45 * un.w) return {{0, top}, {0, top}};
    return {{x, y}, {x + bw, y + bh}};
}
}  // namespace

double left_furniture(cairo_t* cr, const Scene& s, const Units& un, double right) {
    // The legend's column: the annotation above it is one line or two across the top, over
    // the view's edge at most; the legend's rows would cover a band of it.
    if (!s.show_text || !s.legend) return 0.0;
    const double below = !s.title_band && !s.annotation.empty() ? annotation_height(cr, s, un, right) : 2 * un.u;
    return legend_box(cr, s, un, below).hi.x();
}

namespace {
bool meets(const Box& a, const Box& b) {
    return a.lo.x() < b.hi.x() && b.lo.x() < a.hi.x() && a.lo.y() < b.hi.y() && b.lo.y() < a.hi.y();
}
}  // namespace

Box draw_legend(cairo_t* cr, const Scene& s, const Units& un, double top, const std::vector<std::vector<Vec2>>& marks,
                const std::vector<Box>& taken, double right) {
    Box box = legend_box(cr, s, un, top);
    if (box.hi.x() <= box.lo.x()) return box;
    // Top left, unless it would cover what it explains (a touching bench): then the first other
    // corner clear of those and of the furniture already there (clock, scale bar, inset).
    const auto clear = [&](const Box& b) {
        if (b.lo.x() < 0 || b.lo.y() < top || b.hi.x() > right || b.hi.y() > un.h) return false;
        const auto hit = [&](const Box& m) { return meets(b, m); };
        const auto covers = [&](const std::vector<Vec2>& m) { return clip_polygon(m, b.grown(3 * un.u)).size() >= 3; };
        return std::none_of(marks.begin(), marks.end(), covers) && std::none_of(taken.begin(), taken.end(), hit);
    };
    if (!clear(box)) {
        const Vec2 size = box.hi - box.lo;
        const double m = 8 * un.u;
        double bottom = un.h;  // above the furniture at the bottom left (the scale bar)
        for (const Box& t : taken)
            if (t.hi.x() > t.lo.x() && t.lo.x() < 0.5 * un.w && t.hi.y() > 0.5 * un.h) bottom = std::min(bottom, t.lo.y());
        const std::vector<Vec2> corners{{right - m - size.x(), box.lo.y()}, {m, bottom - m - size.y()},
                                        {right - m - size.x(), un.h - m - size.y()}};
        for (const Vec2& c : corners) {
            const Box b{c, c + size};
            if (clear(b)) {
                box = b;
                break;
            }
        }
    }
    const std::vector<Entry> entries = legend_entries(s);
    const double size = un.text(12), row = 1.5 * size, sw = 1.6 * size, sh = 0.6 * size, pad = 8 * un.ut;
    const double x = box.lo.x(), y = box.lo.y(), bw = box.hi.x() - x, bh = box.hi.y() - y;
    backdrop(cr, s.theme, x, y, bw, bh);
    log_placed(cr, LayoutItem::Kind::legend, x, y, x + bw, y + bh, "legend");
    double cy = y + pad + 0.5 * size;
    for (const auto& e : entries) {
        draw_swatch(cr, s, e, x + pad, cy - 0.5 * sh, sw, sh, un.u);
        set_colour(cr, s.theme.text);
        text(cr, s.theme.font, size, x + pad + sw + 0.6 * size, cy, e.label, 0.0, 0.5);
        cy += row;
    }
    return box;
}

Box draw_clock(cairo_t* cr, const Scene& s, const Units& un, double right) {
    if (!s.show_text || (s.clock.empty() && s.rate.empty())) return {{right, 0}, {right, 0}};
    const double big = un.text(17), small = un.text(13), pad = 8 * un.ut;
    // The clock's width is that of its widest reading ("t = 888.888 s"): digits of DejaVu Sans
    // share one advance, so the box keeps still while the time runs.
    std::string widest = s.clock;
    for (char& c : widest)
        if (c >= '0' && c <= '9') c = '8';
    const double tw = std::max(text_width(cr, s.theme.font, big, widest, true), text_width(cr, s.theme.font, small, s.rate));
    const double bh = pad + big + (s.rate.empty() ? 0.0 : 0.5 * small + small) + pad;
    const double x1 = right - 8 * un.u, y0 = 8 * un.u;
    backdrop(cr, s.theme, x1 - tw - 2 * pad, y0, tw + 2 * pad, bh);
    set_colour(cr, s.theme.text);
    text(cr, s.theme.font, big, x1 - pad - tw, y0 + pad + 0.5 * big, s.clock, 0.0, 0.5, true);
    if (!s.rate.empty())
        text(cr, s.theme.font, small, x1 - pad, y0 + pad + big + 0.5 * small + 0.5 * small, s.rate, 1.0, 0.5);
    return {{x1 - tw - 2 * pad, y0}, {x1, y0 + bh}};
}

void draw_captions(cairo_t* cr, const Scene& s, const Units& un, double left, double right, double lift) {
    if (!s.show_text || s.captions.empty()) return;
    const double size = un.text(16), pad = 8 * un.ut, margin = 10 * un.u;
    // Centred on the picture between the bottom corners' furniture; where that leaves too
    // little room for a sentence, at the bottom beside the inset (over the scale bar while it
    // shows: the bar is back when it fades); only with no room there either, above them all.
    const double half = std::min(0.5 * un.w - left, right - 0.5 * un.w) - margin;
    const bool between = 2 * half >= 0.4 * un.w;
    const bool beside = !between && right - 2 * margin >= 0.45 * un.w;
    const double centre = beside ? 0.5 * right : 0.5 * un.w;
    const double room = (between ? 2 * half : beside ? right - 2 * margin : un.w - 2 * margin) - 2 * pad;
    double bottom = between || beside ? un.h - margin : lift - margin;
    for (auto it = s.captions.rbegin(); it != s.captions.rend(); ++it) {
        if (it->opacity <= 0 || it->text.empty()) continue;
        const FittedText t = fit_text(cr, s.theme.font, size, it->text, room, true, 2, un.body_px > 0);
        double tw = 0;
        for (const auto& line : t.lines) tw = std::max(tw, text_width(cr, s.theme.font, t.size, line, true));
        const double line_h = 1.3 * t.size;
        const double bh = 2 * pad + line_h * static_cast<double>(t.lines.size()) - (line_h - t.size);
        const double top = bottom - bh;
        backdrop(cr, s.theme, centre - 0.5 * tw - pad, top, tw + 2 * pad, bh, 0.88 * it->opacity);
        Rgba ink = s.theme.text;
        ink.a *= it->opacity;
        set_colour(cr, ink);
        for (std::size_t i = 0; i < t.lines.size(); ++i)
            text(cr, s.theme.font, t.size, centre, top + pad + 0.5 * t.size + line_h * static_cast<double>(i),
                 t.lines[i], 0.5, 0.5, true);
        bottom = top - 4 * un.u;
    }
}

}  // namespace dragon::render
