// make_scene: a simulated moment turned into a display list in world coordinates.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <fmt/format.h>

#include "dragon/render.hpp"
#include "guide.hpp"
#include "render/words.hpp"

namespace dragon {

namespace {

struct Box {
    double x0 = std::numeric_limits<double>::infinity(), y0 = x0;
    double x1 = -std::numeric_limits<double>::infinity(), y1 = x1;
    void add(const Vec2& p) {
        x0 = std::min(x0, p.x()), y0 = std::min(y0, p.y());
        x1 = std::max(x1, p.x()), y1 = std::max(y1, p.y());
    }
};

Scene::Style style_of(int bench, int bench_count) {
    if (bench == 1) return Scene::Style::head;
    if (bench == bench_count) return Scene::Style::tail;
    return Scene::Style::body;
}

void place_camera(Scene& scene, const Frame& frame, const Camera& cam) {
    switch (cam.mode) {
    case Camera::Mode::fit_dragon: {
        Box box;
        for (const Rect& r : frame.benches)
            for (Vec2 p : corners(r).p) box.add(p);
        if (frame.benches.empty()) box.add({-1, -1}), box.add({1, 1});
        const double w = box.x1 - box.x0, h = box.y1 - box.y0;
        const double pad = cam.margin * std::max(w, h);
        scene.view_centre = {0.5 * (box.x0 + box.x1), 0.5 * (box.y0 + box.y1)};
        scene.view_width = w + 2 * pad;
        scene.view_height = h + 2 * pad;
        return;
    }
    case Camera::Mode::fixed:
        scene.view_centre = cam.centre;
        break;
    case Camera::Mode::follow_head:
        scene.view_centre = frame.handles.empty() ? Vec2::Zero() : frame.handles.front().pos;
        break;
    }
    if (!(cam.extent >= kMinViewExtent && cam.extent <= kMaxViewExtent))
        throw InputError(fmt::format("camera extent {} m is not allowed: use {:g}..{:g} m", cam.extent, kMinViewExtent,
                                     kMaxViewExtent));
    if (!(std::max(std::abs(scene.view_centre.x()), std::abs(scene.view_centre.y())) <= kMaxViewCentre))
        throw InputError(fmt::format("camera centre ({}, {}) is not allowed: each coordinate must be finite and "
                                     "within {:g} m", scene.view_centre.x(), scene.view_centre.y(), kMaxViewCentre));
    scene.view_width = scene.view_height = cam.extent;
}

Rgba guide_colour(const Theme& theme, PathKind kind, int piece) {
    if (kind == PathKind::spiral || piece == 0) return theme.guide;
    // Turnaround: coil-in spiral, the two arcs of the S-curve, then the coil-out spiral.
    return piece <= 2 ? theme.s_curve : theme.guide_out;
}

// The arc ranges of the guide not hidden under a bench. Between two handles the path bulges
// from the chord by the sagitta kappa d^2 / 8; while that stays well inside the board's half
// width the opaque bench covers the path there, and drawing it would only cost time (a whole
// spiral under the dragon is most of a frame's stroking). Where the path curves sharply (the
// S-curve, the head near the centre) the guide is kept.
std::vector<std::pair<double, double>> visible_ranges(const Path& path, const BenchSpec& spec,
                                                      const Frame& frame, double s0, double s1) {
    std::vector<std::pair<double, double>> out;
    double from = s0;  // start of the current visible range
    const int n = static_cast<int>(frame.handles.size()) - 1;
    for (int k = n; k >= 1; --k) {  // links from the tail forward: arc positions increase
        const Place rear = frame.handles[k].place, front = frame.handles[k - 1].place;
        const double kappa = std::max(std::abs(path.curvature(rear)), std::abs(path.curvature(front)));
        const double d = spec.link_length(k);
        if (kappa * d * d / 8.0 >= 0.6 * 0.5 * spec.width) continue;  // visible beside the board
        const double a = path.arc(rear), b = path.arc(front);
        if (a > from) out.push_back({from, a});
        from = std::max(from, b);
    }
    if (s1 > from) out.push_back({from, s1});
    return out;
}

void add_guides(Scene& scene, const Simulation& sim, const Frame& frame, const SceneOptions& opt) {
    const Path& path = sim.path();
    const PathKind kind = sim.scenario().path.kind;
    std::vector<std::pair<double, double>> ranges;
    if (opt.guide_arcs) {
        const auto [s0, s1] = *opt.guide_arcs;
        if (s1 > s0) ranges.push_back({s0, std::min(s1, path.s_max())});
    } else {
        const auto [s0, s1] = guide_arcs_of(sim, frame);
        ranges = visible_ranges(path, sim.scenario().bench, frame, s0, s1);
    }
    for (auto [a, b] : ranges) {
        for (auto [p, q] : render::split_by_piece(path, a, b)) {
            const int piece = path.at_arc(0.5 * (p + q)).place.piece;
            Scene::Guide g;
            g.path = sim.shared_path();
            g.s0 = p;
            g.s1 = q;
            g.colour = guide_colour(scene.theme, kind, piece);
            g.width_px = (kind == PathKind::turnaround && piece >= 1 && piece <= 2) ? 2.0 : 1.0;
            scene.guides.push_back(std::move(g));
        }
    }
}

// Benches lying across each other, past the first contact: in the touching colour, each
// overlap's deepest corner marked, the deepest one labelled with its depth.
void mark_overlaps(Scene& scene, const Frame& frame, Language language) {
    for (const Overlap& o : overlaps(frame)) {
        if (o.depth < kTouchingDepth) break;  // deepest first: the rest only touch
        scene.overlaps.push_back(o);
        for (int k : {o.bench_a, o.bench_b}) scene.benches[static_cast<size_t>(k - 1)].style = Scene::Style::collision;
        scene.markers.push_back({o.point, scene.theme.contact, 3.0, false});
    }
    if (scene.overlaps.empty()) return;
    const Overlap& deepest = scene.overlaps.front();
    scene.labels.push_back({deepest.point,
                            fmt::format(fmt::runtime(render::words(language).overlap), deepest.depth,
                                        deepest.bench_a, deepest.bench_b),
                            scene.theme.collision, 13.0, 6.0, -6.0, deepest.bench_a, 1});
}

// The two touching benches named on the picture, each a little way back along its own board
// from the contact (the label rule moves them clear of everything else): which is the head
// reads without the legend.
void name_touching(Scene& scene, const Frame& frame, const CollisionMark& mark, Language language) {
    const render::Words& w = render::words(language);
    const int n = static_cast<int>(frame.benches.size());
    for (int k : {mark.bench_a, mark.bench_b}) {
        if (k < 1 || k > n) continue;
        const Rect& r = frame.benches[static_cast<std::size_t>(k - 1)];
        const double along = std::clamp(dot(mark.point - r.centre, r.axis), -r.half_length, r.half_length);
        const Vec2 at = r.centre + 0.5 * along * r.axis;  // halfway between the board's middle and the contact
        Label l;
        l.pos = at;
        l.text = k == 1 ? std::string(w.bench_head) : fmt::format(fmt::runtime(w.bench), k);
        l.colour = scene.theme.text;
        l.size_px = 13.0;
        l.bench = k;
        scene.labels.push_back(std::move(l));
    }
}

// The whole dragon small (draw() marks the main view's box on it): where a close-up or a
// followed head is.
std::shared_ptr<const Scene> make_inset(const Simulation& sim, const Frame& frame, const SceneOptions& opt,
                                        const Scene& main) {
    SceneOptions io;
    io.theme = opt.theme;
    io.camera = opt.inset_camera.value_or(Camera::fit());
    io.colour_by_speed = opt.colour_by_speed;
    io.speed_min = main.speed_min;
    io.speed_max = main.speed_max;
    io.show_guides = opt.show_guides;
    io.show_turning_space = opt.show_turning_space;
    io.show_handles = false;
    io.show_scale_bar = io.show_colour_bar = io.show_text = false;
    io.annotation = "";
    io.collision = opt.collision;
    io.highlight_benches = opt.highlight_benches;
    io.mark_overlaps = opt.mark_overlaps;
    return std::make_shared<const Scene>(make_scene(sim, frame, io));
}

}  // namespace

std::pair<double, double> guide_arcs_of(const Simulation& sim, const Frame& frame) {
    const Path& path = sim.path();
    const BenchSpec& spec = sim.scenario().bench;
    double chain_length = 0;
    for (int k = 1; k <= spec.bench_count; ++k) chain_length += spec.link_length(k);
    const Vec2 tail = frame.handles.empty() ? Vec2::Zero() : frame.handles.back().pos;
    const double tail_arc = frame.handles.empty() ? frame.head_arc : path.arc(frame.handles.back().place);
    // Out past the tail by one more turn, and on ahead of the head by a dragon's length (to the
    // centre on the plain spiral), so the guide frames the dragon.
    const double s0 = tail_arc - 2 * std::numbers::pi * norm(tail) - 1.0;
    const double s1 = std::isinf(path.s_max()) ? frame.head_arc + chain_length : path.s_max();
    return {s0, s1};
}

Scene make_scene(const Simulation& sim, const Frame& frame, const SceneOptions& opt) {
    Scene scene;
    scene.theme = opt.theme;
    const Scenario& sc = sim.scenario();
    const int n = static_cast<int>(frame.benches.size());

    place_camera(scene, frame, opt.camera);

    scene.benches.reserve(n);
    double vmin = std::numeric_limits<double>::infinity(), vmax = -vmin;
    for (int k = 1; k <= n; ++k) {
        const double v = 0.5 * (frame.handles[k - 1].speed + frame.handles[k].speed);
        vmin = std::min(vmin, v), vmax = std::max(vmax, v);
        scene.benches.push_back({frame.benches[k - 1], style_of(k, n), v});
    }
    for (int k : opt.highlight_benches)
        if (k >= 1 && k <= n) scene.benches[k - 1].style = Scene::Style::highlight;
    if (opt.collision) {
        for (int k : {opt.collision->bench_a, opt.collision->bench_b})
            if (k >= 1 && k <= n) scene.benches[k - 1].style = Scene::Style::collision;
        scene.collision = opt.collision;
        if (opt.name_touching && opt.show_text) name_touching(scene, frame, *opt.collision, opt.language);
    }
    if (opt.mark_overlaps) mark_overlaps(scene, frame, opt.language);

    scene.handles.reserve(frame.handles.size());
    for (const Handle& h : frame.handles) scene.handles.push_back(h.pos);
    // The hole radius of the board, m: the handle is a pin through it.
    scene.handle_radius = 0.5 * 0.055;

    if (opt.show_guides && !frame.handles.empty()) add_guides(scene, sim, frame, opt);
    if (opt.show_turning_space) scene.turning_radius = sc.path.turn_radius;

    scene.colour_by_speed = opt.colour_by_speed;
    scene.speed_min = opt.speed_min.value_or(n ? vmin : 0.0);
    scene.speed_max = opt.speed_max.value_or(n ? vmax : 1.0);
    if (!(scene.speed_max > scene.speed_min)) scene.speed_max = scene.speed_min + 1e-6;

    scene.show_handles = opt.show_handles;
    scene.show_scale_bar = opt.show_scale_bar;
    scene.show_colour_bar = opt.show_colour_bar;
    scene.show_text = opt.show_text;
    scene.annotation = opt.annotation.value_or(
        fmt::format(fmt::runtime(render::words(opt.language).annotation), frame.time, sc.coil_pitch()));
    scene.title_band = opt.title_band;
    scene.text_px = opt.text_px;
    scene.language = opt.language;
    scene.legend = opt.show_legend;
    scene.legend_touching = opt.collision.has_value() || !scene.overlaps.empty();
    if (opt.show_inset && opt.camera.mode != Camera::Mode::fit_dragon) scene.inset = make_inset(sim, frame, opt, scene);
    return scene;
}

}  // namespace dragon
