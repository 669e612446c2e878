// Fig. 1 done right: one link of the chain. The paper draws two handles and the law of
// cosines; the real question is which root of the chord equation is the next handle (there are
// several, one on each ring the circle of radius d crosses), and how the speeds pass along a
// rigid link.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "figure_kit.hpp"

namespace dragon::fig {

namespace {

// Every arc position s (on the given range) where |P(s) - centre| = d: sign changes on a fine
// grid, then bisection.
std::vector<Vec2> chord_roots(const Path& path, const Vec2& centre, double d, double s0, double s1) {
    std::vector<Vec2> roots;
    auto f = [&](double s) { return distance(path.at_arc(s).pos, centre) - d; };
    const double step = 0.01;
    double a = s0, fa = f(a);
    for (double b = s0 + step; b <= s1; b += step) {
        const double fb = f(b);
        if ((fa < 0) != (fb < 0)) {
            double lo = a, hi = b, flo = fa;
            for (int i = 0; i < 60; ++i) {
                const double mid = 0.5 * (lo + hi), fm = f(mid);
                if ((fm < 0) == (flo < 0)) lo = mid, flo = fm;
                else hi = mid;
            }
            roots.push_back(path.at_arc(0.5 * (lo + hi)).pos);
        }
        a = b, fa = fb;
    }
    return roots;
}

Polyline arrow(const Vec2& from, const Vec2& to, Rgba colour, double width = 2.2) {
    Polyline p = segment(from, to, colour, width);
    p.arrow = true;
    return p;
}

}  // namespace

void link_geometry(const Context& c, const std::string& path) {
    const Simulation sim(c.base);
    // Q1's last moment, or the first contact if it comes sooner.
    const double t = shown_span(sim, 0.0, sim.time_of(300.0), c.answers->contact()).to;
    Frame f = sim.frame(t);
    f.handles.resize(4);  // the head, the first two body benches: the rest would only crowd
    f.benches.resize(3);
    const Theme& th = c.opt.theme;
    const Vec2 h0 = f.handles[0].pos, h1 = f.handles[1].pos, h2 = f.handles[2].pos;
    const BenchSpec& spec = c.base.bench;
    const double d1 = spec.link_length(1), d2 = spec.link_length(2);

    // Frame the two links, the velocity arrows and the circle of roots.
    const double k = 1.3;  // metres of arrow per m/s
    const Vec2 tip0 = h0 + k * f.handles[0].speed * f.handles[0].tangent;
    double x0 = std::min({h0.x(), h2.x(), tip0.x(), h0.x() - d1}), x1 = std::max({h0.x(), h2.x(), tip0.x(), h0.x() + d1});
    double y0 = std::min({h0.y(), h2.y(), tip0.y(), h0.y() - d1}), y1 = std::max({h0.y(), h2.y(), tip0.y(), h0.y() + d1});
    SceneOptions so = c.scene_options();
    so.theme = th;
    so.title_band = true;  // a title hides nothing
    so.show_turning_space = false;
    so.camera = Camera::at({0.5 * (x0 + x1), 0.5 * (y0 + y1)}, std::max(x1 - x0, y1 - y0) + 1.4);
    so.annotation = fmt::format(
        fmt::runtime(c.say(
            "One link at t = {} s: the next handle is the nearest root of |P(s) \u2212 P(s\u2080)| = d behind the head\n"
            "Rigid link: v\u2080 (T\u2080\u00b7u) = v\u2081 (T\u2081\u00b7u), with T the unit tangents and u along the link\n"
            "Boards {:.2f} m (head) and {:.2f} m long, {:.2f} m wide; holes {:.3f} m from the ends",
            "t = {} s 时的一节连杆：下一个把手是弦方程 |P(s) \u2212 P(s\u2080)| = d 在龙头后方最近的根\n"
            "刚性连杆：v\u2080 (T\u2080\u00b7u) = v\u2081 (T\u2081\u00b7u)，T 为单位切向量，u 沿连杆方向\n"
            "龙头板长 {:.2f} m，龙身板长 {:.2f} m，板宽 {:.2f} m；把手孔距板端 {:.3f} m")),
        seconds(t), spec.head_length, spec.body_length, spec.width, spec.hole_offset);
    Scene s = make_scene(sim, f, so);
    s.benches.back().style = Scene::Style::body;  // bench 3 is not the tail: the chain was cut short

    const Rgba ink = th.text, accent = th.collision, soft = with_alpha(th.text, 0.55);
    // The circle of radius d1 about handle 0 and every point where it meets the path.
    s.polylines.push_back(circle(h0, d1, soft, 1.2, true));
    const double s_head = f.head_arc;
    FigureData data{{"point", "x (m)", "y (m)", "speed (m/s)", "tangent x", "tangent y"}, {}};
    for (int i = 0; i <= 2; ++i) {
        const Handle& h = f.handles[static_cast<std::size_t>(i)];
        data.add({fmt::format("handle {}", i), num(h.pos.x()), num(h.pos.y()), num(h.speed), num(h.tangent.x()), num(h.tangent.y())});
    }
    for (Vec2 r : chord_roots(sim.path(), h0, d1, s_head - 80.0, std::min(sim.path().s_max(), s_head + 40.0))) {
        const bool chosen = distance(r, h1) < 1e-6;
        data.add({chosen ? "root chosen (handle 1)" : "other root", num(r.x()), num(r.y()), "", "", ""});
        s.markers.push_back({r, chosen ? accent : soft, chosen ? 6.0 : 5.0, true});
    }
    // At a print size the labels are shorter: the paper's caption says the rest.
    const bool brief = c.print();
    s.labels.push_back(label(h1, brief ? c.say("handle 1", "把手 1") : c.say("handle 1: the nearest root behind", "把手 1：后方最近的根"),
                             accent, 13, 10, 22));
    const auto roots = chord_roots(sim.path(), h0, d1, s_head - 80.0, s_head - 0.5);
    if (roots.size() > 1) s.labels.push_back(label(roots[roots.size() - 2], brief ? c.say("other roots", "其他根") : c.say("other roots of the chord equation", "弦方程的其他根"), soft, 12, 10, 4));

    // Chords, with their lengths.
    Polyline chord1{{h0, h1}, ink, 1.4, true}, chord2{{h1, h2}, ink, 1.4, true};
    s.polylines.push_back(chord1);
    s.polylines.push_back(chord2);
    s.labels.push_back(label(0.5 * (h0 + h1), brief ? fmt::format("d\u2081 = {:.2f} m", d1)
                                                    : fmt::format(fmt::runtime(c.say("d\u2081 = {:.2f} m (head: {:.2f} \u2212 2\u00d7{:.3f})",
                                                                                     "d\u2081 = {:.2f} m（龙头：{:.2f} \u2212 2\u00d7{:.3f}）")),
                                                                  d1, spec.head_length, spec.hole_offset), ink, 13, 70, 30));
    s.labels.push_back(label(0.5 * (h1 + h2), fmt::format("d\u2082 = {:.2f} m", d2), ink, 13, 10, 6));

    // Velocities: v_i T_i at each end of the head link, and the link direction u. Rigidity makes
    // the components along u equal: v0 (T0 . u) = v1 (T1 . u).
    const Vec2 u = normalized(h0 - h1);
    const Handle& a = f.handles[0];
    const Handle& b = f.handles[1];
    s.polylines.push_back(arrow(h0, h0 + k * a.speed * a.tangent, th.tail));
    s.polylines.push_back(arrow(h1, h1 + k * b.speed * b.tangent, th.tail));
    // u beside the link, on the side away from the centre, so that it crowds neither the head
    // bench nor v1's arrow at handle 1.
    Vec2 side = perp(u);
    if (dot(side, 0.5 * (h0 + h1)) < 0) side = -side;
    const Vec2 u_from = 0.5 * (h0 + h1) + 0.75 * side - 0.45 * u;
    s.polylines.push_back(arrow(u_from, u_from + 0.9 * u, th.highlight, 1.6));
    s.labels.push_back(label(h0 + k * a.speed * a.tangent, fmt::format("v\u2080 = {:.6f} m/s", a.speed), th.tail, 13, 6, 14));
    s.labels.push_back(label(h1 + k * b.speed * b.tangent, fmt::format("v\u2081 = {:.6f} m/s", b.speed), th.tail, 13, 6, 14));
    s.labels.push_back(label(u_from + 0.9 * u, "u", th.highlight, 14, 4, -4));
    s.labels.push_back(label(h0, brief ? c.say("handle 0", "把手 0") : c.say("handle 0 (head front)", "把手 0（龙头前把手）"), ink, 13, 10, -10));
    s.labels.push_back(label(h2, c.say("handle 2", "把手 2"), ink, 13, 10, -8));

    write_scene(c, s, 1000, 1000, path);
    write_data(c, path, data);
}

}  // namespace dragon::fig
