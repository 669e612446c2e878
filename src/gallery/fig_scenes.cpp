// Whole-dragon pictures: Fig. 2 (the dragon at 300 s, coloured by its exact speeds) and the
// turnaround in the dark theme.
#include <algorithm>

#include <fmt/format.h>

#include "dragon/turnaround.hpp"
#include "figure_kit.hpp"

namespace dragon::fig {

void dragon_at_300s(const Context& c, const std::string& path) {
    const Simulation sim(c.base);
    // Q1's last moment, or the first contact if it comes sooner (the dragon stops there).
    const std::optional<Contact>& hit = c.answers->contact();
    const double t = shown_span(sim, 0.0, sim.time_of(300.0), hit).to;
    const Frame f = sim.frame(t);
    const char* why = hit && t == hit->time ? " (the first contact)" : t < sim.time_of(300.0) ? " (the end of the run)" : "";
    SceneOptions so;
    so.theme = c.opt.theme;
    so.title_band = true;  // a title hides nothing
    so.colour_by_speed = true;
    const Vec2 head = f.handles.front().pos;
    so.annotation = fmt::format("t = {} s{}   head front at x = {:.6f} m, y = {:.6f} m   pitch {:g} m", seconds(t),
                                why, head.x(), head.y(), c.base.coil_pitch());
    Scene s = make_scene(sim, f, so);
    Label h = label(head, "head", c.opt.theme.text, 14, 8, -8);
    h.bench = 1;
    Label tl = label(f.handles.back().pos, "tail", c.opt.theme.text, 14, 8, -8);
    tl.bench = static_cast<int>(f.benches.size());
    s.labels.push_back(h);
    s.labels.push_back(tl);
    // Coloured by speed: a full palette keeps the colour map smooth.
    write_scene(c, s, c.px(1100), c.px(1000), path, 256);
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
    SceneOptions so;
    so.theme = load_theme("dark", c.opt.asset_dir);
    so.title_band = true;  // a title hides nothing
    so.colour_by_speed = true;
    so.camera = Camera::at({0, 0}, 2.0 * sc.path.turn_radius + 9.0);
    so.annotation = fmt::format("Turnaround at t = {:.1f} s, 1 s after the head leaves the S-curve (orange), pitch {:g} m\n"
                                "The head bench pivots: handles behind it run up to {:.3f} m/s while the head keeps {:g} m/s",
                                t, sc.path.turn_pitch, fastest, sc.head_speed);
    write_scene(c, make_scene(sim, f, so), c.px(1000), c.px(1000), path, 256);
}

}  // namespace dragon::fig
