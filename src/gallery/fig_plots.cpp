// The plots behind the figures: handle speeds along the chain, the S-curve's geometry and the
// speed ratio on the turnaround.
#include <cmath>
#include <numbers>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "dragon/turnaround.hpp"
#include "figure_kit.hpp"

namespace dragon::fig {

void speeds_by_handle(const Context& c, const std::string& path) {
    const Simulation sim(c.base);
    Plot p;
    p.theme = c.opt.theme;
    p.title = "Speed of every handle along the chain (exact, from rigid links)";
    p.note = fmt::format("Coiling in at {:g} m/s, pitch {:g} m.{}", c.base.head_speed, c.base.coil_pitch(),
                         c.contest() ? " The paper's finite differences set the body to 0 at t = 0." : "");
    p.x_label = fmt::format("handle (0 = head front, {} = tail rear)", c.base.bench.bench_count);
    p.y_label = "speed (m/s)";
    p.legend = Plot::Legend::bottom_left;
    // Q1's six moments (0, 60, ..., 300 m of head travel: seconds at 1 m/s), spread over a shorter
    // run if the dragon stops sooner.
    const TimeSpan span = shown_span(sim, 0.0, sim.time_of(300.0), c.answers->contact());
    for (int i = 0; i <= 5; ++i) {
        const double t = span.from + (span.to - span.from) * i / 5;
        const Frame f = sim.frame(t);
        PlotSeries s;
        s.label = fmt::format("t = {} s", seconds(t));
        s.colour = series_colour(p.theme, i);
        for (std::size_t k = 0; k < f.handles.size(); ++k) s.points.push_back({double(k), f.handles[k].speed});
        p.series.push_back(std::move(s));
    }
    p.x_min = 0;
    p.x_max = static_cast<double>(c.base.bench.bench_count);
    write_plot(c, p, c.px(1000), c.px(600), path);
}

void s_curve_geometry(const Context& c, const std::string& path) {
    Scenario sc = c.base;
    sc.path.kind = PathKind::turnaround;
    const SCurve d = design_s_curve(sc);
    const TurnaroundPath tp(d);
    const Theme& th = c.opt.theme;
    Plot p;
    p.theme = th;
    p.title = fmt::format("The turnaround S-curve: two tangent arcs, r\u2081 = {:g} r\u2082", sc.path.arc_ratio);
    p.note = fmt::format("Pitch {:g} m, turning space radius {:g} m: r\u2081 = {:.6f} m, r\u2082 = {:.6f} m, length {:.6f} m",
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
    PlotSeries space{"turning space", {}, th.turning_space, 1.3, true, true};
    for (int i = 0; i <= 200; ++i) {
        const double a = 2 * std::numbers::pi * i / 200;
        space.points.push_back({R * std::cos(a), R * std::sin(a)});
    }
    p.series.push_back(space);
    // About one turn of each spiral either side of the turning space.
    const double turn = 2 * std::numbers::pi * (R + 0.5 * d.pitch);
    p.series.push_back({"coil-in spiral", sample(-turn, 0, 400), th.guide, 1.6});
    p.series.push_back({"coil-out spiral", sample(d.length, d.length + turn, 400), th.guide_out, 1.6});
    p.series.push_back({fmt::format("arc 1, r\u2081 = {:.3f} m", d.r1), sample(0, d.length1, 200), th.s_curve, 3.0});
    p.series.push_back({fmt::format("arc 2, r\u2082 = {:.3f} m", d.r2), sample(d.length1, d.length, 200), th.head, 3.0});
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
    point(d.entry, "A: enters, tangent to the coil-in spiral", th.text, 8, -8, 0.0);
    point(d.exit, "B = \u2212A: leaves, tangent to the coil-out spiral", th.text, -8, 18, 1.0);
    point(d.joint, "joint: the arcs are tangent", th.text, -10, 20, 1.0);
    point(d.c1, "C\u2081", th.s_curve, 6, -6);
    point(d.c2, "C\u2082", th.head, 6, -6);
    point({0, 0}, "O", soft, 6, 16);
    p.x_min = -R - 1.2, p.x_max = R + 1.2, p.y_min = -R - 1.2, p.y_max = R + 1.2;
    write_plot(c, p, c.px(900), c.px(860), path);
}

void speed_ratio_on_turnaround(const Context& c, const std::string& path) {
    Scenario sc = c.base;
    sc.path.kind = PathKind::turnaround;
    const Simulation sim(sc);
    const SCurve d = design_s_curve(sc);
    Plot p;
    p.theme = c.opt.theme;
    p.title = "Largest handle speed over the head's, on the turnaround path";
    p.x_label = "time (s); the head enters the S-curve at 0";
    p.y_label = "max handle speed / head speed";
    p.legend = Plot::Legend::none;
    PlotSeries s{"", {}, series_colour(p.theme, 0), 1.6};
    // Q4's window, 100 m of head travel either side of the turn (100 s at 1 m/s), 1600 samples.
    const TimeSpan span = shown_span(sim, sim.time_of(-100.0), sim.time_of(100.0), std::nullopt);
    for (int i = 0; i <= 1600; ++i) {
        const double t = span.from + (span.to - span.from) * i / 1600;
        s.points.push_back({t, speed_ratio_at(sim.path(), sc.bench, sim.head_arc(t)).ratio});
    }
    p.series.push_back(s);
    p.ref_lines.push_back({true, 0.0, fmt::format("S-curve: 0 to {:.1f} s", d.length / sc.head_speed), p.theme.s_curve});
    p.ref_lines.push_back({true, d.length / sc.head_speed, "", p.theme.s_curve});
    // The marked maximum is Q5's, refined between samples (the curve's own peak sits a little
    // lower: the samples straddle it).
    const MaxSpeed q5 = max_head_speed(sc, 2.0, kTurnaroundWindow);
    const bool run = q5.tied.size() > 1 && q5.tied.back() - q5.tied.front() + 1 == static_cast<int>(q5.tied.size());
    const std::string who = run                    ? fmt::format("handles {}-{}", q5.tied.front(), q5.tied.back())
                            : q5.tied.size() > 1 ? fmt::format("handles {}", fmt::join(q5.tied, ", "))
                                                 : fmt::format("handle {}", q5.handle);
    p.labels.push_back({{q5.time, q5.ratio}, fmt::format("max {:.6f} at t = {:.6f} s", q5.ratio, q5.time),
                        p.theme.text, 10, 4, 13, true});
    p.y_max = 1.0 + 1.12 * (q5.ratio - 1.0);
    p.note = fmt::format("Sampled every {:g} s; the maximum refined ({}). Head speed limit: 2 / {:.6f} = {:.6f} m/s.",
                         (span.to - span.from) / 1600, who, q5.ratio, q5.max_head_speed);
    write_plot(c, p, c.px(1000), c.px(600), path);
}

}  // namespace dragon::fig
