// The collision figures: Fig. 3 (the broad phase around one bench), Fig. 4 (the first contact,
// zoomed in), Fig. 5 (the state at several pitches around the true minimum) and the clearance
// against time.
#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "dragon/analyses.hpp"
#include "dragon/cairo_handles.hpp"
#include "dragon/collision.hpp"
#include "render/figure_kit.hpp"

namespace dragon::fig {

namespace {

Contact coil_in_contact(const Simulation& sim) {
    auto c = first_contact(sim, 0.0, sim.end_time());
    if (!c) throw std::runtime_error("this scenario coils in to the centre without a collision: no contact to draw");
    return *c;
}

double bounding_radius(const Rect& r) { return std::hypot(r.half_length, r.half_width); }

Polyline segment(Vec2 a, Vec2 b, Rgba colour, double width, bool dashed = false) {
    Polyline p;
    p.points = {a, b};
    p.colour = colour;
    p.width_px = width;
    p.dashed = dashed;
    return p;
}

void paint(const Scene& s, int w, int h, const std::string& path) {
    cairo::Surface surface(cairo_image_surface_create(CAIRO_FORMAT_RGB24, w, h));
    cairo::Context cr = cairo::make_context(surface.get());
    draw(cr.get(), s, w, h);
    write_png(surface.get(), path);
}

// The time the head front handle reaches the turning-space boundary on a plain spiral.
double boundary_time(const Simulation& sim) {
    const auto& spiral = static_cast<const Spiral&>(sim.path());
    const double theta_end = sim.scenario().path.turn_radius / spiral.b();
    return (-spiral.length_to(theta_end) - sim.start_arc()) / sim.scenario().head_speed;
}

}  // namespace

void broad_phase(const Context& c, const std::string& path) {
    const Simulation sim(c.base);
    const Contact hit = coil_in_contact(sim);
    const Frame& f = hit.frame;
    const Theme& th = c.opt.theme;
    const int focus = 1;  // the head: the bench that collides first
    const double margin = 1.0;  // the clearance search's margin, m
    const Rect& r = f.benches[focus - 1];
    // The sweep band: the bench's bounding box on x, widened by half the margin each side (as in
    // candidate_pairs; a bench whose own band overlaps it goes on to the circle test).
    const double reach = r.half_length * std::abs(r.axis.x) + r.half_width * std::abs(r.axis.y) + 0.5 * margin;

    std::vector<int> candidates;
    for (auto [i, j] : candidate_pairs(f, margin))
        if (i == focus || j == focus) candidates.push_back(i == focus ? j : i);

    SceneOptions so;
    so.theme = th;
    so.camera = Camera::at(r.centre, 11.0);
    so.highlight_benches = candidates;
    so.annotation = fmt::format(
        "Broad phase around bench {} at the first contact (t = {:.2f} s): {} of {} benches are candidates\n"
        "Sweep and prune on x (box extents), then bounding circles within a margin of {:g} m (purple); only these get the exact test.",
        focus, hit.time, candidates.size(), f.benches.size() - 2, margin);
    Scene s = make_scene(sim, f, so);

    // The sweep on x, then the circle test: a candidate's bounding circle comes within the
    // margin of the focus bench's.
    const double x0 = r.centre.x - reach, x1 = r.centre.x + reach;
    for (double x : {x0, x1}) s.polylines.push_back(segment({x, r.centre.y - 8}, {x, r.centre.y + 8}, th.text, 1.2, true));
    for (int bench : candidates) {
        const Rect& b = f.benches[bench - 1];
        s.polylines.push_back(circle(b.centre, bounding_radius(b), with_alpha(th.highlight, 0.45), 1.0));
    }
    s.polylines.push_back(circle(r.centre, bounding_radius(r) + margin, th.head, 2.2, true));
    s.polylines.push_back(circle(r.centre, bounding_radius(r), th.head, 1.6));
    s.labels.push_back(label(r.centre + Vec2{0, bounding_radius(r) + margin}, "bench 1's bounding circle + margin", th.head, 14, 6, -8));
    s.labels.push_back(label({x1, r.centre.y - 4.6}, "sweep band on x", th.text, 14, 6, 0));
    paint(s, c.px(900), c.px(900), path);
}

void first_contact_zoom(const Context& c, const std::string& path) {
    const Simulation sim(c.base);
    const Contact hit = coil_in_contact(sim);
    const Frame& f = hit.frame;
    const Theme& th = c.opt.theme;
    const Rect& a = f.benches[hit.bench_a - 1];
    const Rect& b = f.benches[hit.bench_b - 1];
    const Vec2 p = contact_point(a, b);
    const double extent = 2.4;

    SceneOptions so;
    so.theme = th;
    so.camera = Camera::at(p, extent);
    so.collision = CollisionMark{hit.bench_a, hit.bench_b, p};
    so.annotation = fmt::format("First contact at t = {:.6f} s: bench {} touches bench {} (head at r = {:.4f} m)",
                                hit.time, hit.bench_a, hit.bench_b, hit.head_radius);
    Scene s = make_scene(sim, f, so);
    // Name each touching bench beside the contact, along its own axis.
    auto name_at = [&](const Rect& r, int bench) {
        const double along = std::clamp(dot(p - r.centre, r.axis), -r.half_length, r.half_length);
        const double back = along > 0 ? -0.55 : 0.55;
        const Vec2 at = r.centre + (along + back) * r.axis;
        std::string name = bench == 1 ? "bench 1 (head)" : fmt::format("bench {}", bench);
        s.labels.push_back(label(at, name, th.text, 15, -40, -16));
    };
    name_at(a, hit.bench_a);
    name_at(b, hit.bench_b);
    const Separation sep = separation(a, b);
    s.labels.push_back(label(p, fmt::format("contact: separation {:.1e} m", sep.distance), th.text, 13, 16, 26));
    // The handles near the contact, numbered: those well inside the view, so that no number
    // hides under the title band or runs off the edge.
    for (std::size_t i = 0; i < f.handles.size(); ++i)
        if (const Vec2 d = f.handles[i].pos - p; std::abs(d.x) < 0.46 * extent && d.y > -0.46 * extent && d.y < 0.43 * extent)
            s.labels.push_back(label(f.handles[i].pos, fmt::format("{}", i), with_alpha(th.text, 0.7), 12, 8, 14));

    const int w = c.px(1000), h = c.px(1000);
    cairo::Surface surface(cairo_image_surface_create(CAIRO_FORMAT_RGB24, w, h));
    cairo::Context cr = cairo::make_context(surface.get());
    draw(cr.get(), s, w, h);
    // An inset: the whole dragon, the zoomed square marked.
    SceneOptions io;
    io.theme = th;
    io.show_text = false;
    io.show_scale_bar = false;
    io.collision = so.collision;
    Scene inset = make_scene(sim, f, io);
    const double half = 0.5 * extent;
    inset.polylines.push_back({{p + Vec2{-half, -half}, p + Vec2{half, -half}, p + Vec2{half, half}, p + Vec2{-half, half}},
                               th.collision, 2.0, false, true});
    const int iw = w * 3 / 10;
    cairo_save(cr.get());
    cairo_translate(cr.get(), w - iw - 12, h - iw - 12);
    cairo_rectangle(cr.get(), 0, 0, iw, iw);
    cairo_clip(cr.get());
    draw(cr.get(), inset, iw, iw);
    cairo_restore(cr.get());
    cairo_set_source_rgb(cr.get(), th.text.r, th.text.g, th.text.b);
    cairo_set_line_width(cr.get(), 1.5);
    cairo_rectangle(cr.get(), w - iw - 12.5, h - iw - 12.5, iw + 1, iw + 1);
    cairo_stroke(cr.get());
    write_png(surface.get(), path);
}

void pitch_states(const Context& c, const std::string& path) {
    const Theme& th = c.opt.theme;
    // Six pitches 5 mm apart across the neighbourhood of the minimum. The exact minimum is
    // `dragon min-pitch`'s job: bisecting to 1e-10 m needs runs at pitches whose clearance
    // stays near zero for minutes of simulated time, far too slow for a gallery. The title
    // states the bracket these panels prove.
    const std::vector<double> pitches{0.440, 0.445, 0.450, 0.455, 0.460, 0.470};
    std::vector<Scene> panels;
    std::vector<double> touching, clear;
    std::vector<std::string> captions;
    for (double pitch : pitches) {
        Scenario sc = c.base;
        sc.path.pitch = pitch;
        const Simulation sim(sc);
        SceneOptions so;
        so.theme = th;
        so.camera = Camera::at({0, 0}, 2 * sc.path.turn_radius + 7.0);
        so.show_scale_bar = false;
        so.annotation = "";
        const auto hit = contact_before_boundary(c.base, pitch);
        (hit ? touching : clear).push_back(pitch);
        Frame f;
        if (hit) {
            f = hit->frame;
            const Vec2 q = contact_point(f.benches[hit->bench_a - 1], f.benches[hit->bench_b - 1]);
            so.collision = CollisionMark{hit->bench_a, hit->bench_b, q};
            captions.push_back(fmt::format("pitch {:.3f} m: benches {} and {} touch at t = {:.2f} s", pitch, hit->bench_a,
                                        hit->bench_b, hit->time));
        } else {
            f = sim.frame(boundary_time(sim));
            captions.push_back(fmt::format("pitch {:.3f} m: the head reaches r = {:g} m, no contact", pitch,
                                           sc.path.turn_radius));
        }
        panels.push_back(make_scene(sim, f, so));
    }
    const int pw = c.px(440), ph = c.px(440), gap = 6, caption_h = c.px(24);
    const int cols = 3, rows = 2;
    const int title_h = c.px(40);
    const int w = cols * pw + (cols + 1) * gap, h = rows * (ph + caption_h) + (rows + 1) * gap + title_h;
    cairo::Surface surface(cairo_image_surface_create(CAIRO_FORMAT_RGB24, w, h));
    cairo::Context cr = cairo::make_context(surface.get());
    cairo_set_source_rgb(cr.get(), th.background.r, th.background.g, th.background.b);
    cairo_paint(cr.get());
    cairo_save(cr.get());
    cairo_translate(cr.get(), 0, title_h);
    draw_panels(cr.get(), panels, captions, cols, pw, ph, caption_h, th, gap);
    cairo_restore(cr.get());
    cairo_set_source_rgb(cr.get(), th.text.r, th.text.g, th.text.b);
    cairo_select_font_face(cr.get(), th.font.c_str(), CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
    cairo_set_font_size(cr.get(), 18.0 * c.opt.scale);
    cairo_move_to(cr.get(), gap + 8, title_h * 0.7);
    // The bracket the panels prove: the largest pitch that touches, and the next one up (from
    // which every panel is clear).
    std::string verdict = "no pitch here reaches the boundary clear";
    if (!clear.empty()) {
        double below = 0, above = 0;
        for (std::size_t i = pitches.size(); i-- > 0;) {
            if (std::find(touching.begin(), touching.end(), pitches[i]) != touching.end()) {
                below = pitches[i];
                above = i + 1 < pitches.size() ? pitches[i + 1] : 0;
                break;
            }
            above = pitches[i];
        }
        verdict = below > 0 ? fmt::format("the smallest collision-free pitch lies in ({:.3f}, {:.3f}] m", below, above)
                            : fmt::format("every pitch from {:.3f} m reaches the boundary clear", above);
    }
    const std::string title = fmt::format("Coiling in to the turning space (r = {:g} m): {} (the paper says 0.42 m)",
                                          c.base.path.turn_radius, verdict);
    cairo_show_text(cr.get(), title.c_str());
    write_png(surface.get(), path);
}

void clearance_over_time(const Context& c, const std::string& path) {
    const Simulation sim(c.base);
    const Contact hit = coil_in_contact(sim);
    Plot p;
    p.theme = c.opt.theme;
    p.title = "Clearance: the smallest gap between non-adjacent benches";
    p.note = fmt::format("Exact rectangle distances. First contact at t = {:.6f} s (benches {} and {}); the paper's 0.1 s grid gives 413 s.",
                         hit.time, hit.bench_a, hit.bench_b);
    p.x_label = "time (s)";
    p.y_label = "clearance (m)";
    p.legend = Plot::Legend::none;
    PlotSeries s{"", {}, series_colour(p.theme, 0), 1.6};
    Frame f;
    auto add = [&](double t) {
        sim.frame_into(t, f);
        s.points.push_back({t, clearance(f).distance});
    };
    for (double t = 0; t < hit.time - 6.0; t += 1.0) add(t);
    for (double t = std::max(0.0, hit.time - 6.0); t < hit.time; t += 0.02) add(t);
    add(hit.time);
    p.series.push_back(s);
    p.ref_lines.push_back({true, hit.time, fmt::format("{:.4f} s", hit.time), p.theme.collision});
    p.ref_lines.push_back({false, 0.0, "", with_alpha(p.theme.text, 0.6)});
    p.x_min = 0;
    p.x_max = std::ceil(hit.time / 50.0) * 50.0;
    p.y_min = -0.02;
    write_plot(p, c.px(1000), c.px(600), path);
}

}  // namespace dragon::fig
