// Film's constructor: each shot's runs resolved (first contacts searched, the turning space and
// the end of the valid motion located), checked against the valid motion, timed, and the shots
// laid end to end with their crossfades.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "film_plan.hpp"
#include "dragon/scenario.hpp"

namespace dragon {

namespace {

using film::ShotPlan;
using film::ViewPlan;

// As for any film (an hour at 240 fps is 864 000 frames).
constexpr long max_frames = kMaxFilmFrames;
struct Resolver {
    const Storyboard& board;
    int shot;
    std::string name;
    [[noreturn]] void fail(const std::string& key, const std::string& why) const {
        throw StoryboardError(board.file, shot, name, key, why);
    }
    // InputErrors of the library named by the key that led to them.
    template <typename F>
    auto named(const std::string& key, F&& f) const {
        try {
            return f();
        } catch (const StoryboardError&) {
            throw;
        } catch (const InputError& e) {
            // A value the library names by its key: said with the storyboard's name for it.
            if (e.key() != Key::none && !dynamic_cast<const ScenarioError*>(&e))
                fail(key, fmt::format("{} {} is not allowed: {}", key_info(e.key()).name, e.value(), e.allowed()));
            fail(key, e.what());
        }
    }

    // The run's first contact: the motion's (collide's over the path's default window), or the
    // earliest over a run that starts before that window.
    void find_contact(ViewPlan& v, const std::string& key) const {
        if (v.contact) return;
        const Simulation& sim = *v.sim;
        const CollideAnswer a = named(key, [&] {
            if (v.spec.from.anchor == TimeRef::Anchor::time || v.spec.from.anchor == TimeRef::Anchor::travel) {
                const double from = time(v, v.spec.from, key);
                return first_contact_covering(sim, from, from);
            }
            return first_contact_of_motion(sim);
        });
        if (!a.contact)
            fail(key, fmt::format("no two benches touch between t = {:g} s and {:.6f} s on this scenario", a.window.from,
                                  a.window.to));
        // The chain collided before the motion (or the shot) starts: said as such, not as an
        // empty stretch of film.
        if (a.overlap)
            fail(key, "there is no first contact to film: the chain collides before it moves: " +
                          overlap_sentence(*a.overlap, a.asked.from));
        const Contact& c = *a.contact;
        v.contact = CollisionMark{c.bench_a, c.bench_b, c.point};
        v.contact_time = c.time;
    }

    double time(ViewPlan& v, const TimeRef& r, const std::string& key) const {
        switch (r.anchor) {
        case TimeRef::Anchor::time: return r.offset;
        case TimeRef::Anchor::travel: return v.sim->time_of(r.offset);
        case TimeRef::Anchor::collision: find_contact(v, key); return v.contact_time + r.offset;
        case TimeRef::Anchor::boundary: return boundary_time(*v.sim) + r.offset;
        case TimeRef::Anchor::end: {
            const double end = named(key, [&] { return v.sim->valid_end(); });
            if (!std::isfinite(end)) fail(key, "'end' is not allowed here: the dragon follows this path for ever; give a time");
            return end + r.offset;
        }
        }
        return r.offset;
    }
};

void plan_view(const Resolver& r, const Shot& shot, ViewPlan& v, const std::string& prefix, double fps) {
    const auto key = [&](const char* k) { return prefix + k; };
    v.sim = std::make_shared<const Simulation>(v.spec.scenario);
    v.from = r.time(v, v.spec.from, key("from"));
    v.to = r.time(v, v.spec.to, key("to"));
    if (!(v.to > v.from)) r.fail(key("to"), fmt::format("to = {:.6f} s is not after from = {:.6f} s", v.to, v.from));
    r.named(key("from"), [&] { v.sim->require_valid(v.from, Key::from); });
    r.named(key("to"), [&] { v.sim->require_valid(v.to, Key::to); });
    for (const Window* w : {&v.spec.camera.from, v.spec.camera.to ? &*v.spec.camera.to : nullptr})
        if (w && w->kind == Window::Kind::contact) r.find_contact(v, key("camera"));
    if (shot.freeze.zoom) r.find_contact(v, "freeze.zoom");
    v.ends_on_contact = v.contact && v.to == v.contact_time;
    v.fit = fit_over(*v.sim, v.from, v.to);
    const CameraMove& cam = v.spec.camera;
    const auto same = [](const Window& a, const Window& b) {
        return a.kind == b.kind && a.centre == b.centre && a.extent == b.extent;
    };
    if (cam.from.kind != Window::Kind::head && (!cam.to || same(cam.from, *cam.to)))
        v.guide_arcs = guide_arcs_over(*v.sim, v.from, v.to);
    if (v.spec.speed_colours) v.speeds = speed_range_over(*v.sim, v.from, v.to);

    std::optional<film::Slow> slow;
    if (shot.slow) {
        const double at = r.time(v, shot.slow->at, "slow.at");
        slow = film::Slow{at, shot.slow->within, shot.slow->rate};
    }
    if (shot.duration && slow) {
        // However fast the rest runs, the slow stretch takes this long.
        const double least = film::TimeMap(v.from, v.to, 1e12, slow).seconds();
        if (least >= *shot.duration)
            r.fail("duration", fmt::format("{:g} s is too short for its slow motion: that alone lasts {:.3g} s of film",
                                           *shot.duration, least));
    }
    const double rate = shot.rate ? *shot.rate : film::TimeMap::rate_for(v.from, v.to, *shot.duration, slow);
    v.map = film::TimeMap(v.from, v.to, rate, slow);
    const double steps = v.map.seconds() * fps;
    if (steps > max_frames) r.fail(shot.rate ? "rate" : "duration", fmt::format("the shot would have {:.3g} frames", steps));
    v.moving = static_cast<int>(std::ceil(steps - 1e-9)) + 1;
}

// The captions of a view: the run's events and the storyboard's own, each on its frames.
void plan_captions(const Resolver& r, const Shot& shot, ViewPlan& v, int count, double fps) {
    const auto frame_of = [&](double t) {
        return std::clamp(static_cast<int>(std::ceil(v.map.film_at(t) * fps - 1e-9)), 0, v.moving - 1);
    };
    const auto add = [&](const std::string& text, double t, double seconds) {
        const int first = frame_of(t);
        const bool last = t >= v.to;
        const int end = last ? count : std::min(count, first + static_cast<int>(std::lround(seconds * fps)));
        v.captions.push_back({text, first, end, last});
    };
    if (shot.events)
        for (const FilmEvent& e : clip_events(*v.sim, v.from, v.to, v.ends_on_contact ? v.contact : std::nullopt,
                                                  r.board.film.language))
            add(e.caption, e.time, 3.0);
    for (std::size_t i = 0; i < shot.captions.size(); ++i) {
        const CaptionSpec& c = shot.captions[i];
        const std::string key = fmt::format("captions[{}].at", i + 1);
        const double t = c.at ? r.time(v, *c.at, key) : v.from;
        if (t < v.from || t > v.to)
            r.fail(key, fmt::format("t = {:.6f} s lies outside the shot ({:.6f} .. {:.6f} s)", t, v.from, v.to));
        add(c.text, t, c.seconds);
    }
    std::stable_sort(v.captions.begin(), v.captions.end(),
                     [](const film::CaptionSpan& a, const film::CaptionSpan& b) { return a.first < b.first; });
}

// Can every frame be drawn? The ends of the run and of the freeze hold the views furthest apart.
void check_drawable(const Resolver& r, const Film& film, int index, const ShotPlan& p, int w, int h) {
    for (std::size_t k = 0; k < p.views.size(); ++k)
        for (int local : {0, p.moving - 1, p.count - 1}) {
            const Scene s = film.scene_at(index, local, static_cast<int>(k));
            const int pw = p.views.size() > 1 ? (w - 6) / 2 : w;
            r.named("camera", [&] { require_drawable(s, pw, h); });
        }
}

}  // namespace

Film::Film(const Storyboard& board, RunOutputs* outputs) : impl_(std::make_unique<Impl>()) {
    Impl& m = *impl_;
    m.settings = board.film;
    m.file = board.file;
    const double fps = board.film.fps;
    try {
        m.theme = load_theme(board.film.theme, board.asset_dir, outputs);
    } catch (const InputError& e) {
        throw StoryboardError(board.file, 0, "film", "theme", e.what());
    }
    for (std::size_t i = 0; i < board.shots.size(); ++i) {
        const Shot& shot = board.shots[i];
        const Resolver r{board, static_cast<int>(i + 1), shot.name};
        ShotPlan p;
        p.shot = shot;
        if (shot.kind == Shot::Kind::title) {
            p.moving = p.count = std::max(1, static_cast<int>(std::lround(*shot.duration * fps)));
        } else {
            for (std::size_t k = 0; k < shot.views.size(); ++k) {
                ViewPlan v;
                v.spec = shot.views[k];
                plan_view(r, shot, v, shot.views.size() > 1 ? fmt::format("split[{}].", k + 1) : "", fps);
                p.moving = std::max(p.moving, v.moving);
                p.views.push_back(std::move(v));
            }
            p.count = p.moving + static_cast<int>(std::lround(shot.freeze.seconds * fps));
            for (ViewPlan& v : p.views) plan_captions(r, shot, v, p.count, fps);
        }
        p.fade = static_cast<int>(std::lround(shot.crossfade * fps));
        if (p.fade > 0 && i == 0) r.fail("transition", "the first shot has no shot before it to fade from");
        if (i > 0) {
            ShotPlan& prev = m.shots.back();
            if (p.fade > std::min(prev.count, p.count))
                r.fail("transition.crossfade", fmt::format("{:g} s is longer than this shot ({:.3g} s) or the one "
                                                           "before ({:.3g} s)", shot.crossfade, p.count / fps,
                                                           prev.count / fps));
            if (p.fade + prev.fade > prev.count)
                r.fail("transition", fmt::format("its crossfade overlaps the one into shot {}: that shot lasts {:.3g} s, "
                                                 "less than the two crossfades ({:g} s and {:g} s)", i, prev.count / fps,
                                                 prev.fade / fps, p.fade / fps));
            p.first = prev.first + prev.count - p.fade;
        }
        m.shots.push_back(std::move(p));
        if (static_cast<long>(m.shots.back().first) + m.shots.back().count > max_frames)
            r.fail("duration", fmt::format("the film would have more than {} frames", max_frames));
    }
    for (const ShotPlan& p : m.shots) m.spans.push_back({p.first, p.count, p.fade});
    m.frames = m.shots.back().first + m.shots.back().count;
    for (std::size_t i = 0; i < m.shots.size(); ++i)
        if (m.shots[i].shot.kind != Shot::Kind::title)
            check_drawable(Resolver{board, static_cast<int>(i + 1), m.shots[i].shot.name}, *this, static_cast<int>(i),
                           m.shots[i], m.settings.width, m.settings.height);
}

Film::~Film() = default;

const FilmSettings& Film::settings() const { return impl_->settings; }
int Film::frame_count() const { return impl_->frames; }
const std::vector<Film::ShotSpan>& Film::spans() const { return impl_->spans; }

double Film::time_at(int shot, int local, int view) const {
    const ViewPlan& v = impl_->shots.at(static_cast<std::size_t>(shot)).views.at(static_cast<std::size_t>(view));
    if (local >= v.moving - 1) return v.to;
    return v.map.time_at(local / impl_->settings.fps);
}

}  // namespace dragon
