// The plots behind the figures: handle speeds along the chain, the S-curve's geometry and the
// speed ratio on the turnaround.
#include <cmath>
#include <numbers>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "dragon/turnaround.hpp"
#include "figure_kit.hpp"

namespace dragon::fig {

namespace {
// A colour two thirds as bright: a guide's shade made to read as a line of a plot.
Rgba darker(Rgba c) { return {0.66 * c.r, 0.66 * c.g, 0.66 * c.b, c.a}; }
}  // namespace

void speeds_by_handle(const Context& c, const std::string& path) {
    const Simulation sim(c.base);
    Plot p;
    p.theme = c.opt.theme;
    p.title = c.say("Speed of every handle along the chain (exact, from rigid links)", "龙身各把手的速度（由刚性连杆精确求得）");
    p.note = fmt::format(fmt::runtime(c.say("Coiling in at {:g} m/s, pitch {:g} m.{}", "以 {:g} m/s 盘入，螺距 {:g} m。{}")),
                         c.base.head_speed, c.base.coil_pitch(),
                         c.contest() ? c.say(" The paper's finite differences set the body to 0 at t = 0.",
                                             "论文的有限差分在 t = 0 时把龙身速度算成 0。")
                                     : "");
    p.x_label = fmt::format(fmt::runtime(c.say("handle (0 = head front, {} = tail rear)", "把手（0 = 龙头前把手，{} = 龙尾后把手）")),
                            c.base.bench.bench_count);
    p.y_label = c.say("speed (m/s)", "速度 (m/s)");
    p.legend = Plot::Legend::bottom_left;
    // Q1's six moments (0, 60, ..., 300 m of head travel: seconds at 1 m/s), spread over a shorter
    // run if the dragon stops sooner.
    const TimeSpan span = shown_span(sim, 0.0, sim.time_of(300.0), c.answers->contact());
    FigureData data{{"t (s)", "handle", "speed (m/s)"}, {}};
    for (int i = 0; i <= 5; ++i) {
        const double t = span.from + (span.to - span.from) * i / 5;
        const Frame f = sim.frame(t);
        PlotSeries s;
        s.label = fmt::format("t = {} s", seconds(t));
        s.colour = series_colour(p.theme, i);
        for (std::size_t k = 0; k < f.handles.size(); ++k) {
            s.points.push_back({double(k), f.handles[k].speed});
            data.add({num(t), std::to_string(k), num(f.handles[k].speed)});
        }
        p.series.push_back(std::move(s));
    }
    p.x_min = 0;
    p.x_max = static_cast<double>(c.base.bench.bench_count);
    write_plot(c, p, 1000, 600, path);
    write_data(c, path, data);
}

void s_curve_geometry(const Context& c, const std::string& path) {
    Scenario sc = c.base;
    sc.path.kind = PathKind::turnaround;
    const SCurve d = design_s_curve(sc);
    const TurnaroundPath tp(d);
    const Theme& th = c.opt.theme;
    Plot p;
    p.theme = th;
    p.title = fmt::format(fmt::runtime(c.say("The turnaround S-curve: two tangent arcs, r\u2081 = {:g} r\u2082, entering tangent to "
                                             "the coil-in spiral at A and leaving tangent to the coil-out one at B",
                                             "调头 S 形曲线：两段相切圆弧，r\u2081 = {:g} r\u2082，在 A 处与盘入螺线相切进入，在 B 处与盘出螺线相切离开")),
                          sc.path.arc_ratio);
    p.note = fmt::format(fmt::runtime(c.say("Pitch {:g} m, turning space radius {:g} m: r\u2081 = {:.6f} m, r\u2082 = {:.6f} m, "
                                            "length {:.6f} m",
                                            "螺距 {:g} m，调头空间半径 {:g} m：r\u2081 = {:.6f} m，r\u2082 = {:.6f} m，长度 {:.6f} m")),
                         d.pitch, sc.path.turn_radius, d.r1, d.r2, d.length);
    p.x_label = "x (m)";
    p.y_label = "y (m)";
    p.equal_aspect = true;
    p.legend = Plot::Legend::bottom_right;
    const double R = sc.path.turn_radius;

    auto sample = [&](double s0, double s1, int n) {
        std::vector<Vec2> pts;
        for (int i = 0; i <= n; ++i) pts.push_back(tp.at_arc(s0 + (s1 - s0) * i / n).pos);
        return pts;
    };
    PlotSeries space{c.say("turning space", "调头空间"), {}, th.turning_space, 1.3, true, true};
    for (int i = 0; i <= 200; ++i) {
        const double a = 2 * std::numbers::pi * i / 200;
        space.points.push_back({R * std::cos(a), R * std::sin(a)});
    }
    p.series.push_back(space);
    // About one turn of each spiral either side of the turning space.
    const double turn = 2 * std::numbers::pi * (R + 0.5 * d.pitch);
    // The two spirals told apart by more than a shade of grey: the coil-out one dashed and both
    // drawn darker than the guides of a scene.
    p.series.push_back({c.say("coil-in spiral", "盘入螺线"), sample(-turn, 0, 400), darker(th.guide), 1.6});
    PlotSeries out{c.say("coil-out spiral", "盘出螺线"), sample(d.length, d.length + turn, 400), darker(th.guide_out), 1.6};
    out.dashed = true;
    p.series.push_back(out);
    p.series.push_back({fmt::format(fmt::runtime(c.say("arc 1, r\u2081 = {:.3f} m", "圆弧 1，r\u2081 = {:.3f} m")), d.r1), sample(0, d.length1, 200), th.s_curve, 3.0});
    p.series.push_back({fmt::format(fmt::runtime(c.say("arc 2, r\u2082 = {:.3f} m", "圆弧 2，r\u2082 = {:.3f} m")), d.r2), sample(d.length1, d.length, 200), th.head, 3.0});
    // Radii to the tangent points: each centre lies on the normal at both ends of its arc,
    // and the joint lies on the line of centres.
    const Rgba soft = with_alpha(th.text, 0.6);
    p.series.push_back({"", {d.c1, d.entry}, soft, 1.0, true, true});
    p.series.push_back({"", {d.c1, d.joint, d.c2}, soft, 1.0, true, true});
    p.series.push_back({"", {d.c2, d.exit}, soft, 1.0, true, true});
    auto point = [&](const Vec2& at, std::string text, Rgba col, double dx, double dy, double align = 0.0) {
        PlotLabel l{at, std::move(text), col, dx, dy, 13, true, align};
        p.labels.push_back(l);
    };
    point(d.entry, c.say("A: entry", "A：入口"), th.text, 8, -8, 0.0);
    point(d.exit, c.say("B = \u2212A: exit", "B = \u2212A：出口"), th.text, -8, -10, 1.0);
    point(d.joint, c.say("joint", "切点"), th.text, 8, 18, 0.0);
    point(d.c1, "C\u2081", th.s_curve, 6, -6);
    point(d.c2, "C\u2082", th.head, 6, -6);
    point({0, 0}, "O", soft, 6, 16);
    p.x_min = -R - 1.2, p.x_max = R + 1.2, p.y_min = -R - 1.2, p.y_max = R + 1.2;
    write_plot(c, p, 900, 860, path);
    // The curve's pieces as drawn (arc position s along the turnaround path, 0 at A), then its
    // named points.
    FigureData data{{"piece", "s (m)", "x (m)", "y (m)"}, {}};
    const auto piece = [&](const char* name, double s0, double s1, int n) {
        for (int i = 0; i <= n; ++i) {
            const double s = s0 + (s1 - s0) * i / n;
            const Vec2 q = tp.at_arc(s).pos;
            data.add({name, num(s), num(q.x()), num(q.y())});
        }
    };
    piece("coil-in spiral", -turn, 0, 400);
    piece("arc 1", 0, d.length1, 200);
    piece("arc 2", d.length1, d.length, 200);
    piece("coil-out spiral", d.length, d.length + turn, 400);
    for (const auto& [name, q] : {std::pair<const char*, Vec2>{"A (entry)", d.entry}, {"joint", d.joint}, {"B (exit)", d.exit},
                                  {"C1 (centre of arc 1)", d.c1}, {"C2 (centre of arc 2)", d.c2}})
        data.add({name, "", num(q.x()), num(q.y())});
    write_data(c, path, data);
}

void speed_ratio_on_turnaround(const Context& c, const std::string& path) {
    Scenario sc = c.base;
    sc.path.kind = PathKind::turnaround;
    const Simulation sim(sc);
    const SCurve d = design_s_curve(sc);
    Plot p;
    p.theme = c.opt.theme;
    p.title = c.say("Largest handle speed over the head's, on the turnaround path", "调头路径上把手最大速度与龙头速度之比");
    p.x_label = c.say("time (s); the head enters the S-curve at 0", "时间 (s)；龙头在 0 时进入 S 形曲线");
    p.y_label = c.print() ? c.say("speed ratio", "速度比") : c.say("max handle speed / head speed", "把手最大速度 / 龙头速度");
    p.legend = Plot::Legend::none;
    PlotSeries s{"", {}, series_colour(p.theme, 0), 1.6};
    FigureData data{{"t (s)", "speed ratio (max handle speed / head speed)"}, {}};
    // Q4's window, 100 m of head travel either side of the turn (100 s at 1 m/s), 1600 samples.
    const TimeSpan span = shown_span(sim, sim.time_of(-100.0), sim.time_of(100.0), std::nullopt);
    for (int i = 0; i <= 1600; ++i) {
        const double t = span.from + (span.to - span.from) * i / 1600;
        s.points.push_back({t, speed_ratio_at(sim.path(), sc.bench, sim.head_arc(t)).ratio});
        data.add({num(t), num(s.points.back().y())});
    }
    p.series.push_back(s);
    p.ref_lines.push_back({true, 0.0, fmt::format(fmt::runtime(c.say("S-curve: 0 to {:.1f} s", "S 形曲线：0 至 {:.1f} s")),
                                                  d.length / sc.head_speed), p.theme.s_curve});
    p.ref_lines.push_back({true, d.length / sc.head_speed, "", p.theme.s_curve});
    // The marked maximum is Q5's, refined between samples (the curve's own peak sits a little
    // lower: the samples straddle it).
    const MaxSpeed q5 = max_head_speed(sc, 2.0, kTurnaroundWindow);
    const bool run = q5.tied.size() > 1 && q5.tied.back() - q5.tied.front() + 1 == static_cast<int>(q5.tied.size());
    const std::string who = run ? fmt::format(fmt::runtime(c.say("handles {}-{}", "把手 {}–{}")), q5.tied.front(), q5.tied.back())
                            : q5.tied.size() > 1 ? fmt::format(fmt::runtime(c.say("handles {}", "把手 {}")), fmt::join(q5.tied, ", "))
                                                 : fmt::format(fmt::runtime(c.say("handle {}", "把手 {}")), q5.handle);
    // Left of the peak, below the S-curve's label at the top.
    p.labels.push_back({{q5.time, q5.ratio},
                        c.print() ? fmt::format(fmt::runtime(c.say("max {:.6f}", "最大 {:.6f}")), q5.ratio)
                                  : fmt::format(fmt::runtime(c.say("max {:.6f} at t = {:.6f} s", "最大 {:.6f}，t = {:.6f} s")),
                                                q5.ratio, q5.time),
                        p.theme.text, -8, 4, 13, true, 1.0});
    p.y_max = 1.0 + 1.35 * (q5.ratio - 1.0);
    p.note = fmt::format(fmt::runtime(c.say("Sampled every {:g} s; the maximum refined ({}). Head speed limit: 2 / {:.6f} = {:.6f} m/s.",
                                            "每 {:g} s 采样一次；最大值经细化（{}）。龙头速度上限：2 / {:.6f} = {:.6f} m/s。")),
                         (span.to - span.from) / 1600, who, q5.ratio, q5.max_head_speed);
    write_plot(c, p, 1000, 600, path);
    write_data(c, path, data);
}

}  // namespace dragon::fig
