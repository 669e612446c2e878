// The label-placement rule. Each label in turn tries places around its point, nearest first:
// its preferred offset, then the eight directions at growing distances. A place costs what it
// hides and what hides it: its part outside the picture, overlap with labels already placed and
// with the screen furniture, benches other than the one it names under it, lines crossing it,
// and a little for every pixel it moves away. The cheapest wins, so two labels never fight for a
// spot, and one pushed away keeps a leader line to its point.
#include "labels.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "render/paint.hpp"

namespace dragon::render {

namespace {

double overlap(const Box& a, const Box& b) {
    const double w = std::min(a.hi.x(), b.hi.x()) - std::max(a.lo.x(), b.lo.x());
    const double h = std::min(a.hi.y(), b.hi.y()) - std::max(a.lo.y(), b.lo.y());
    return w > 0 && h > 0 ? w * h : 0.0;
}

double area(const Box& b) { return (b.hi.x() - b.lo.x()) * (b.hi.y() - b.lo.y()); }

// Does segment pq cross the box (or lie in it)? Liang-Barsky on its parameter.
bool crosses(const Box& b, const Vec2& p, const Vec2& q) {
    double t0 = 0, t1 = 1;
    const Vec2 d = q - p;
    const double pp[4] = {-d.x(), d.x(), -d.y(), d.y()};
    const double qq[4] = {p.x() - b.lo.x(), b.hi.x() - p.x(), p.y() - b.lo.y(), b.hi.y() - p.y()};
    for (int i = 0; i < 4; ++i) {
        if (pp[i] == 0) {
            if (qq[i] < 0) return false;
            continue;
        }
        const double t = qq[i] / pp[i];
        if (pp[i] < 0) t0 = std::max(t0, t);
        else t1 = std::min(t1, t);
        if (t0 > t1) return false;
    }
    return true;
}

// A convex quadrilateral in pixels, with its bounding box for a quick reject.
struct Quad {
    std::array<Vec2, 4> p;
    Box box;
    bool holds(const Vec2& q) const {
        if (!box.holds(q)) return false;
        double sign = 0;
        for (int i = 0; i < 4; ++i) {
            const double c = cross(p[(i + 1) % 4] - p[i], q - p[i]);
            if (c * sign < 0) return false;
            if (c != 0) sign = c;
        }
        return true;
    }
};

struct Obstacles {
    std::vector<Quad> benches;                  // with their bench numbers
    std::vector<int> numbers;
    std::vector<std::pair<Vec2, Vec2>> lines;   // segments of the polylines and the markers' boxes
    std::vector<Box> boxes;                     // furniture, markers and labels placed so far
};

Obstacles gather(const Scene& s, const std::function<Vec2(Vec2)>& px, const Box& world, const std::vector<Box>& taken) {
    Obstacles o;
    const Box seen = world.grown(40);
    for (std::size_t k = 0; k < s.benches.size(); ++k) {
        const Corners c = corners(s.benches[k].rect);
        Quad q;
        Box b{{1e300, 1e300}, {-1e300, -1e300}};
        for (int i = 0; i < 4; ++i) {
            q.p[static_cast<std::size_t>(i)] = px(c.p[static_cast<std::size_t>(i)]);
            b.lo = {std::min(b.lo.x(), q.p[static_cast<std::size_t>(i)].x()), std::min(b.lo.y(), q.p[static_cast<std::size_t>(i)].y())};
            b.hi = {std::max(b.hi.x(), q.p[static_cast<std::size_t>(i)].x()), std::max(b.hi.y(), q.p[static_cast<std::size_t>(i)].y())};
        }
        q.box = b;
        if (overlap(b, seen) <= 0) continue;
        o.benches.push_back(q);
        o.numbers.push_back(static_cast<int>(k) + 1);
    }
    for (const Polyline& pl : s.polylines)
        for (std::size_t i = 0; i + 1 < pl.points.size(); ++i) o.lines.push_back({px(pl.points[i]), px(pl.points[i + 1])});
    o.boxes = taken;
    return o;
}

struct Placed {
    Box box;
    double cost;
};

double cost_of(const Box& b, const Label& l, const Obstacles& o, const Box& world, double moved) {
    const double a = std::max(area(b), 1.0);
    // Any part off the picture costs more than everything else together: a label crossing many
    // lines inside is still read, one cut at the edge is not.
    const double off = 1.0 - overlap(b, world) / a;
    double c = off > 1e-9 ? 1e4 + 1000.0 * off : 0.0;
    // Text over text (another label, the legend, the clock) reads as neither: nearly as bad as
    // leaving the picture.
    for (const Box& t : o.boxes) c += 400.0 * overlap(b, t) / a;
    // Benches under the label: the share of a 7 x 3 grid of its points on one it does not name.
    int under = 0;
    for (int i = 0; i < 7; ++i)
        for (int j = 0; j < 3; ++j) {
            const Vec2 q{b.lo.x() + (b.hi.x() - b.lo.x()) * (i + 0.5) / 7, b.lo.y() + (b.hi.y() - b.lo.y()) * (j + 0.5) / 3};
            for (std::size_t k = 0; k < o.benches.size(); ++k)
                if ((o.numbers[k] < l.bench || o.numbers[k] >= l.bench + l.benches) && o.benches[k].holds(q)) {
                    ++under;
                    break;
                }
        }
    c += 12.0 * under / 21.0;
    for (const auto& [p, q] : o.lines) c += crosses(b, p, q) ? 6.0 : 0.0;
    return c + 0.015 * moved;
}

}  // namespace

void draw_labels(cairo_t* cr, const Scene& s, const Units& un, const std::function<Vec2(Vec2)>& px,
                 const std::vector<Box>& taken, const Box& world) {
    if (!s.show_text || s.labels.empty()) return;
    Obstacles o = gather(s, px, world, taken);
    for (const Label& l : s.labels) {
        const Vec2 p = px(l.pos);
        if (!world.grown(un.w + un.h).holds(p)) continue;  // far outside the picture: none of it could show
        // A point under the furniture (the inset, the legend) cannot be seen: nor can its label.
        if (std::any_of(taken.begin(), taken.end(), [&](const Box& b) { return b.holds(p); })) continue;
        const double size = un.text(l.size_px);
        // Wider than the picture (a long name in Chinese at a column's width): wrapped, at its size.
        const double room = std::max(0.0, world.hi.x() - world.lo.x() - 8 * un.u);
        const std::vector<std::string> lines =
            text_width(cr, s.theme.font, size, l.text) <= room ? std::vector<std::string>{l.text}
                                                               : fit_text(cr, s.theme.font, size, l.text, room, false, 2, true).lines;
        double tw = 0;
        for (const std::string& line : lines) tw = std::max(tw, text_width(cr, s.theme.font, size, line));
        const double lh = 1.25 * size, more = lh * static_cast<double>(lines.size() - 1);
        const double asc = 0.76 * size, desc = 0.24 * size + more, pad = 2 * un.u;
        // A box with its first baseline's left end at (x, y).
        const auto at = [&](double x, double y) { return Box{{x - pad, y - asc - pad}, {x + tw + pad, y + desc + pad}}; };
        const Vec2 want{p.x() + l.dx_px * un.u, p.y() + l.dy_px * un.u};
        Placed best{at(want.x(), want.y()), std::numeric_limits<double>::infinity()};
        const auto consider = [&](double x, double y) {
            const double moved = std::hypot(x - want.x(), y - want.y()) / un.u;
            const Box b = at(x, y);
            const double c = cost_of(b, l, o, world, moved);
            if (c < best.cost) best = {b, c};
        };
        consider(want.x(), want.y());
        for (double r : {6.0, 14.0, 26.0, 44.0, 70.0, 110.0}) {
            const double d = r * un.u, e = 0.7 * d;
            consider(p.x() + d, p.y() + 0.5 * (asc - desc));     // right
            consider(p.x() - d - tw, p.y() + 0.5 * (asc - desc)); // left
            consider(p.x() - 0.5 * tw, p.y() - d - desc);         // above
            consider(p.x() - 0.5 * tw, p.y() + d + asc);          // below
            consider(p.x() + e, p.y() - e - desc);                // above right
            consider(p.x() - e - tw, p.y() - e - desc);           // above left
            consider(p.x() + e, p.y() + e + asc);                 // below right
            consider(p.x() - e - tw, p.y() + e + asc);            // below left
        }
        // The wanted place moved in from the picture's edges, where it would leave the picture.
        consider(std::clamp(want.x(), world.lo.x() + pad, std::max(world.lo.x() + pad, world.hi.x() - pad - tw)),
                 std::clamp(want.y(), world.lo.y() + pad + asc, std::max(world.lo.y() + pad + asc, world.hi.y() - pad - desc)));
        const Box& b = best.box;
        // A leader line when the label sits away from its point.
        const Vec2 near{std::clamp(p.x(), b.lo.x(), b.hi.x()), std::clamp(p.y(), b.lo.y(), b.hi.y())};
        if (std::hypot(near.x() - p.x(), near.y() - p.y()) > 16 * un.u) {
            Rgba c = l.colour;
            c.a *= 0.7;
            set_colour(cr, c);
            cairo_set_line_width(cr, un.u);
            cairo_move_to(cr, p.x(), p.y());
            cairo_line_to(cr, near.x(), near.y());
            cairo_stroke(cr);
            o.lines.push_back({p, near});
        }
        // Where no clear place was near enough, a backdrop under the text keeps it legible on
        // whatever it covers (a red name on purple benches).
        if (best.cost >= 1.0) backdrop(cr, s.theme, b.lo.x(), b.lo.y(), b.hi.x() - b.lo.x(), b.hi.y() - b.lo.y(), 0.85);
        for (std::size_t i = 0; i < lines.size(); ++i)
            halo_text(cr, s.theme.font, size, b.lo.x() + pad, b.lo.y() + pad + asc + lh * static_cast<double>(i), lines[i],
                      l.colour, s.theme.background, 3.0 * un.ut);
        o.boxes.push_back(b);
    }
}

}  // namespace dragon::render
