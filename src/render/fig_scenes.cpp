// Whole-dragon pictures: Fig. 2 (the dragon at 300 s, coloured by its exact speeds) and the
// turnaround in the dark theme.
#include <algorithm>

#include <fmt/format.h>

#include "dragon/cairo_handles.hpp"
#include "dragon/turnaround.hpp"
#include "render/figure_kit.hpp"

namespace dragon::fig {

namespace {
// Both pictures are coloured by speed: a full palette keeps the colour map smooth.
void paint(const Scene& s, int w, int h, const std::string& path) {
    cairo::Surface surface(cairo_image_surface_create(CAIRO_FORMAT_RGB24, w, h));
    cairo::Context cr = cairo::make_context(surface.get());
    draw(cr.get(), s, w, h);
    write_png(surface.get(), path, 256);
}
}  // namespace

void dragon_at_300s(const Context& c, const std::string& path) {
    const Simulation sim(c.base);
    const Frame f = sim.frame(300.0);
    SceneOptions so;
    so.theme = c.opt.theme;
    so.colour_by_speed = true;
    const Vec2 head = f.handles.front().pos;
    so.annotation = fmt::format("t = 300 s   head front at ({:.6f}, {:.6f})   pitch {:g} m", head.x, head.y,
                                c.base.coil_pitch());
    Scene s = make_scene(sim, f, so);
    s.labels.push_back(label(head, "head", c.opt.theme.text, 14, 8, -8));
    s.labels.push_back(label(f.handles.back().pos, "tail", c.opt.theme.text, 14, 40, 6));
    paint(s, c.px(1100), c.px(1000), path);
}

void turnaround_scene(const Context& c, const std::string& path) {
    Scenario sc = c.base;
    sc.path.kind = PathKind::turnaround;
    const Simulation sim(sc);
    // One second after the head leaves the S-curve: the handles behind it are still turning
    // and run fastest about then (see plot_speed_ratio).
    const double t = design_s_curve(sc).length / sc.head_speed + 1.0;
    const Frame f = sim.frame(t);
    double fastest = 0;
    for (const Handle& h : f.handles) fastest = std::max(fastest, h.speed);
    SceneOptions so;
    so.theme = load_theme("dark");
    so.colour_by_speed = true;
    so.camera = Camera::at({0, 0}, 2.0 * sc.path.turn_radius + 9.0);
    so.annotation = fmt::format("Turnaround at t = {:.1f} s, 1 s after the head leaves the S-curve (orange), pitch {:g} m\n"
                                "The head bench pivots: handles behind it run up to {:.3f} m/s while the head keeps {:g} m/s",
                                t, sc.path.turn_pitch, fastest, sc.head_speed);
    paint(make_scene(sim, f, so), c.px(1000), c.px(1000), path);
}

}  // namespace dragon::fig
