// Whole-dragon pictures: Fig. 2 (the dragon at 300 s, coloured by its exact speeds) and the
// turnaround in the dark theme.
#include <algorithm>

#include <fmt/format.h>

#include "dragon/turnaround.hpp"
#include "figure_kit.hpp"

namespace dragon::fig {

namespace {
// Every handle of the frame: where it is and how fast it moves.
FigureData handle_table(const Frame& f) {
    FigureData d{{"t (s)", "handle", "x (m)", "y (m)", "speed (m/s)"}, {}};
    for (std::size_t k = 0; k < f.handles.size(); ++k)
        d.add({num(f.time), std::to_string(k), num(f.handles[k].pos.x()), num(f.handles[k].pos.y()), num(f.handles[k].speed)});
    return d;
}
}  // namespace

void dragon_at_300s(const Context& c, const std::string& path) {
    const Simulation sim(c.base);
    // Q1's last moment, or the first contact if it comes sooner (the dragon stops there).
    const std::optional<Contact>& hit = c.answers->contact();
    const double t = shown_span(sim, 0.0, sim.time_of(300.0), hit).to;
    const Frame f = sim.frame(t);
    const char* why = hit && t == hit->time       ? c.say(" (the first contact)", "（首次碰撞）")
                      : t < sim.time_of(300.0) ? c.say(" (the end of the run)", "（运动的终点）")
                                               : "";
    SceneOptions so = c.scene_options();
    so.theme = c.opt.theme;
    so.title_band = true;  // a title hides nothing
    so.colour_by_speed = true;
    const Vec2 head = f.handles.front().pos;
    so.annotation = fmt::format(fmt::runtime(c.say("t = {} s{}   head front at x = {:.6f} m, y = {:.6f} m   pitch {:g} m",
                                                    "t = {} s{}   龙头前把手位于 x = {:.6f} m，y = {:.6f} m   螺距 {:g} m")),
                                seconds(t), why, head.x(), head.y(), c.base.coil_pitch());
    Scene s = make_scene(sim, f, so);
    Label h = label(head, c.say("head", "龙头"), c.opt.theme.text, 14, 8, -8);
    h.bench = 1;
    Label tl = label(f.handles.back().pos, c.say("tail", "龙尾"), c.opt.theme.text, 14, 8, -8);
    tl.bench = static_cast<int>(f.benches.size());
    s.labels.push_back(h);
    s.labels.push_back(tl);
    // Coloured by speed: a full palette keeps the colour map smooth.
    write_scene(c, s, 1100, 1000, path, 256);
    write_data(c, path, handle_table(f));
}

void turnaround_scene(const Context& c, const std::string& path) {
    Scenario sc = c.base;
    sc.path.kind = PathKind::turnaround;
    const Simulation sim(sc);
    // One second after the head leaves the S-curve: the handles behind it are still turning
    // and run fastest about then (see plot_speed_ratio).
    const double t = shown_span(sim, 0.0, design_s_curve(sc).length / sc.head_speed + 1.0, std::nullopt).to;
    const Frame f = sim.frame(t);
    double fastest = 0;
    for (const Handle& h : f.handles) fastest = std::max(fastest, h.speed);
    SceneOptions so = c.scene_options();
    so.theme = load_theme("dark", c.opt.asset_dir, c.opt.outputs);
    so.title_band = true;  // a title hides nothing
    so.colour_by_speed = true;
    so.camera = Camera::at({0, 0}, 2.0 * sc.path.turn_radius + 9.0);
    so.annotation = fmt::format(
        fmt::runtime(c.say("Turnaround at t = {:.1f} s, 1 s after the head leaves the S-curve (orange), pitch {:g} m\n"
                           "The head bench pivots: handles behind it run up to {:.3f} m/s while the head keeps {:g} m/s",
                           "调头：t = {:.1f} s，龙头离开 S 形曲线（橙色）后 1 s，螺距 {:g} m\n"
                           "龙头板凳在转动：其后的把手速度高达 {:.3f} m/s，而龙头保持 {:g} m/s")),
        t, sc.path.turn_pitch, fastest, sc.head_speed);
    write_scene(c, make_scene(sim, f, so), 1000, 1000, path, 256);
    write_data(c, path, handle_table(f));
}

}  // namespace dragon::fig
