// Film frames on demand: a shot's scene at one of its frames (camera, clock, captions), title
// cards, split screens and crossfades. Called from several render threads at once: it only
// reads the plan.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "render/cairo_handles.hpp"
#include "film_plan.hpp"
#include "render/backdrop.hpp"
#include "render/paint.hpp"
#include "render/words.hpp"

namespace dragon {

namespace {

using film::ShotPlan;
using film::ViewPlan;

double ease(Ease e, double u) {
    u = std::clamp(u, 0.0, 1.0);
    return e == Ease::linear ? u : u * u * (3 - 2 * u);
}

struct View2 {
    Vec2 centre = Vec2::Zero();
    double extent;
};

View2 resolve(const Window& w, const ViewPlan& v, const Frame& f) {
    switch (w.kind) {
    case Window::Kind::fit: return {v.fit.centre, v.fit.extent};
    case Window::Kind::head: return {f.handles.front().pos, w.extent};
    case Window::Kind::fixed: return {w.centre, w.extent};
    case Window::Kind::contact: return {v.contact ? v.contact->point : Vec2::Zero(), w.extent};
    }
    return {v.fit.centre, v.fit.extent};
}

// Centres move in a straight line; the extent zooms evenly in its logarithm, so halving the
// view takes as long at 20 m as at 2 m.
View2 between(const View2& a, const View2& b, double u) {
    return {a.centre + u * (b.centre - a.centre), std::exp((1 - u) * std::log(a.extent) + u * std::log(b.extent))};
}

bool is_fit(const CameraMove& c) { return c.from.kind == Window::Kind::fit && (!c.to || c.to->kind == Window::Kind::fit); }

void draw_title_card(cairo_t* cr, const Theme& th, const Shot& shot, int w, int h, double text_px) {
    const double ut = text_px > 0 ? text_px / 12.0 : std::max(std::min(w, h) / 800.0, kMinTextPx / 13.0);
    const bool keep = text_px > 0;  // at a print size: wrapped, never smaller
    render::set_colour(cr, {th.background.r, th.background.g, th.background.b, 1.0});
    cairo_paint(cr);
    const render::FittedText title = render::fit_text(cr, th.font, 44 * ut, shot.title, 0.86 * w, true, 2, keep);
    const render::FittedText sub = render::fit_text(cr, th.font, 20 * ut, shot.subtitle, 0.8 * w, false, 3, keep);
    const double title_h = 1.25 * title.size * static_cast<double>(title.lines.size());
    const double sub_h = 1.4 * sub.size * static_cast<double>(sub.lines.size());
    double y = 0.5 * (h - title_h - (sub.lines.empty() ? 0.0 : 1.2 * sub.size + sub_h)) + 0.5 * title.size;
    render::set_colour(cr, th.text);
    for (const auto& line : title.lines) {
        render::text(cr, th.font, title.size, 0.5 * w, y + 0.4 * title.size, line, 0.5, 0.5, true);
        y += 1.25 * title.size;
    }
    if (sub.lines.empty()) return;
    // A rule in the head's colour between title and subtitle: the film's one accent.
    render::set_colour(cr, th.head);
    cairo_rectangle(cr, 0.5 * w - 40 * ut, y, 80 * ut, 3 * ut);
    cairo_fill(cr);
    y += 1.2 * sub.size;
    render::set_colour(cr, th.text);
    for (const auto& line : sub.lines) {
        render::text(cr, th.font, sub.size, 0.5 * w, y + 0.5 * sub.size, line, 0.5, 0.5);
        y += 1.4 * sub.size;
    }
}

constexpr double split_gap = 6;  // px between the two scenes of a split shot

}  // namespace

Scene Film::scene_at(int shot, int local, int view) const {
    const ShotPlan& p = impl_->shots.at(static_cast<std::size_t>(shot));
    const ViewPlan& v = p.views.at(static_cast<std::size_t>(view));
    const Shot& sh = p.shot;
    const double fps = impl_->settings.fps;
    const double t = time_at(shot, local, view);
    const Frame f = v.sim->frame(t);

    const CameraMove& cam = v.spec.camera;
    const double u = v.moving > 1 ? std::min(local, v.moving - 1) / double(v.moving - 1) : 1.0;
    View2 at = between(resolve(cam.from, v, f), resolve(cam.to.value_or(cam.from), v, f), ease(cam.ease, u));
    const bool closing_in = sh.freeze.zoom && local >= p.moving;
    if (closing_in) {
        // The freeze closes in on the contact (or the head) over its first 60 %, then holds.
        const double frames = std::max(1.0, 0.6 * (p.count - p.moving));
        const Vec2 target = v.ends_on_contact ? v.contact->point : f.handles.front().pos;
        at = between(at, {target, *sh.freeze.zoom}, ease(Ease::in_out, (local - p.moving + 1) / frames));
    }

    SceneOptions so;
    so.theme = impl_->theme;
    so.camera = Camera::at(at.centre, at.extent);
    so.colour_by_speed = v.spec.speed_colours;
    if (v.speeds) so.speed_min = v.speeds->lo, so.speed_max = v.speeds->hi;
    so.show_guides = so.show_turning_space = v.spec.guides;
    so.annotation = v.spec.label ? *v.spec.label : scenario_line(v.spec.scenario, impl_->settings.language);
    so.language = impl_->settings.language;
    so.show_legend = sh.legend && view == 0;
    so.show_inset = sh.inset && (!is_fit(cam) || closing_in);
    so.show_text = sh.text;
    so.text_px = impl_->settings.text_px;
    so.inset_camera = v.fit;
    so.guide_arcs = v.guide_arcs;
    if (v.ends_on_contact && t == v.to) so.collision = v.contact;
    Scene s = make_scene(*v.sim, f, so);
    s.legend_touching = v.ends_on_contact;
    if (sh.clock) {
        const render::Words& w = render::words(impl_->settings.language);
        s.clock = fmt::format(fmt::runtime(w.clock), t);
        s.rate = local >= v.moving ? std::string(w.held) : fmt::format("\u00d7{:.2g}", v.map.rate_at(t));
    }
    // One caption at a time: the latest to come up.
    for (auto it = v.captions.rbegin(); it != v.captions.rend(); ++it)
        if (local >= it->first && local < it->end) {
            const double out = it->to_the_end ? 1.0 : std::clamp((it->end - local) / (0.5 * fps), 0.0, 1.0);
            s.captions.push_back({it->text, out});
            break;
        }
    return s;
}

namespace {

void paint_shot(const Film& film, const film::ShotPlan& p, int shot, int local, cairo_t* cr, const Theme& th, int w,
                int h, render::BackdropCache& backdrop) {
    if (p.shot.kind == Shot::Kind::title) {
        draw_title_card(cr, th, p.shot, w, h, film.settings().text_px);
        return;
    }
    if (p.views.size() == 1) {
        render::draw_reusing_backdrop(cr, film.scene_at(shot, local, 0), w, h, backdrop);
        return;
    }
    // Two scenes side by side, each in its own half, a gap of the theme's grid colour between.
    render::set_colour(cr, {th.grid.r, th.grid.g, th.grid.b, 1.0});
    cairo_paint(cr);
    const int pw = static_cast<int>((w - split_gap) / 2);
    for (int k = 0; k < 2; ++k) {
        cairo_save(cr);
        cairo_translate(cr, k == 0 ? 0 : w - pw, 0);
        cairo_rectangle(cr, 0, 0, pw, h);
        cairo_clip(cr);
        draw(cr, film.scene_at(shot, local, k), pw, h);
        cairo_restore(cr);
    }
}

}  // namespace

void Film::paint(int index, cairo_t* cr) const {
    const Impl& m = *impl_;
    const int w = m.settings.width, h = m.settings.height;
    int k = static_cast<int>(m.shots.size()) - 1;
    while (k > 0 && m.shots[static_cast<std::size_t>(k)].first > index) --k;
    const ShotPlan& p = m.shots[static_cast<std::size_t>(k)];
    const int local = index - p.first;
    if (k == 0 || local >= p.fade) {
        paint_shot(*this, p, k, local, cr, m.theme, w, h, *m.backdrop);
        return;
    }
    // A crossfade: the shot before, then this one over it, more opaque frame by frame.
    const ShotPlan& before = m.shots[static_cast<std::size_t>(k - 1)];
    paint_shot(*this, before, k - 1, index - before.first, cr, m.theme, w, h, *m.backdrop);
    cairo::Surface next(cairo_image_surface_create(CAIRO_FORMAT_RGB24, w, h));
    {
        cairo::Context nc(cairo_create(next.get()));
        paint_shot(*this, p, k, local, nc.get(), m.theme, w, h, *m.backdrop);
    }
    cairo_surface_flush(next.get());
    cairo_save(cr);
    cairo_set_source_surface(cr, next.get(), 0, 0);
    cairo_paint_with_alpha(cr, (local + 1.0) / (p.fade + 1.0));
    cairo_restore(cr);
}

}  // namespace dragon
