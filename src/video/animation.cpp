// A clip of simulated time as a sequence of scenes, and its encoding.
#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "dragon/scenario.hpp"
#include "dragon/video.hpp"
#include "dragon/look.hpp"
#include "render/backdrop.hpp"
#include "render/words.hpp"

namespace dragon {

namespace {

// A held last moment is drawn once, but every second of it is still encoded (about 700 frames/s
// of a still 720p picture here): an hour is the longest still a film can sensibly end on.
constexpr double max_hold = 3600.0;  // s
// Moments the fixed view and the speed range are fitted to.
constexpr int camera_samples = 9;

struct Box {
    double lo_x = std::numeric_limits<double>::infinity(), lo_y = lo_x;
    double hi_x = -std::numeric_limits<double>::infinity(), hi_y = hi_x;
    void add(const Vec2& p) {
        lo_x = std::min(lo_x, p.x());
        lo_y = std::min(lo_y, p.y());
        hi_x = std::max(hi_x, p.x());
        hi_y = std::max(hi_y, p.y());
    }
};

double sample_time(double from, double to, int i) { return from + (to - from) * i / (camera_samples - 1); }

}  // namespace

Camera fit_over(const Simulation& sim, double from, double to, double margin) {
    Box box;
    for (int i = 0; i < camera_samples; ++i)
        for (const Rect& r : sim.frame(sample_time(from, to, i)).benches)
            for (Vec2 p : corners(r).p) box.add(p);
    if (!std::isfinite(box.lo_x)) return Camera::at({0, 0}, 2.0);  // no benches
    const double w = box.hi_x - box.lo_x, h = box.hi_y - box.lo_y;
    const double extent = std::max(w, h) * (1.0 + 2.0 * margin);
    return Camera::at({0.5 * (box.lo_x + box.hi_x), 0.5 * (box.lo_y + box.hi_y)}, extent);
}

std::pair<double, double> guide_arcs_over(const Simulation& sim, double from, double to) {
    std::pair<double, double> arcs = guide_arcs_of(sim, sim.frame(from));
    for (int i = 1; i < camera_samples; ++i) {
        const auto [s0, s1] = guide_arcs_of(sim, sim.frame(sample_time(from, to, i)));
        arcs = {std::min(arcs.first, s0), std::max(arcs.second, s1)};
    }
    return arcs;
}

SpeedRange speed_range_over(const Simulation& sim, double from, double to) {
    // Speeds peak briefly (handles just behind the head as it leaves the S-curve): far more
    // moments than the view needs, each a chain solve of some 16 us.
    constexpr int speed_samples = 257;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    Frame f;
    for (int i = 0; i < speed_samples; ++i) {
        sim.frame_into(from + (to - from) * i / (speed_samples - 1), f);
        for (const Handle& h : f.handles) {
            lo = std::min(lo, h.speed);
            hi = std::max(hi, h.speed);
        }
    }
    return {lo, std::max(hi, lo + 1e-9)};
}

std::string scenario_line(const Scenario& s, Language language) {
    const render::Words& w = render::words(language);
    return fmt::format(fmt::runtime(s.path.kind == PathKind::spiral ? w.coiling_in_line : w.turnaround_line),
                       s.coil_pitch(), s.head_speed);
}

Animation::Animation(const Simulation& sim, Clip clip, double fps, SceneOptions scene,
                     std::optional<CollisionMark> end_mark, FilmLook look)
    : sim_(&sim), clip_(clip), fps_(fps), scene_(std::move(scene)), end_mark_(end_mark), look_(std::move(look)) {
    // Named in the library's terms (the CLI words them with its flags: cli/error_words.cpp).
    const std::string range = fmt::format("{}..{} s", clip.from, clip.to);
    if (!std::isfinite(clip.from) || !std::isfinite(clip.to))
        throw InputError(Key::time_range, range, "both ends must be finite seconds");
    if (!(clip.to > clip.from)) throw InputError(Key::time_range, range, "its end must come after its start");
    // A film never shows a moment past the end of the valid motion (nor past the path's end).
    sim.require_valid(clip.from, Key::from);
    sim.require_valid(clip.to, Key::to);
    if (!(fps > 0.0) || !std::isfinite(fps)) throw InputError(Key::fps, error_value(fps), "use a rate above 0");
    if (!(clip.speedup > 0.0) || !std::isfinite(clip.speedup))
        throw InputError(Key::speedup, error_value(clip.speedup), "use simulated seconds per video second above 0");
    if (!(clip.hold >= 0.0 && clip.hold <= max_hold))
        throw InputError(Key::hold, error_value(clip.hold), fmt::format("use 0..{:g} seconds", max_hold));

    const double steps = (clip.to - clip.from) * fps / clip.speedup;
    const double hold_frames = std::round(clip.hold * fps);
    if (steps + hold_frames + 1 > kMaxFilmFrames)
        throw InputError(Key::film_frame_count, fmt::format("{:.3g}", steps + hold_frames + 1),
                         fmt::format("a film has at most {} frames; use fewer frames per second or more simulated "
                                     "seconds per second of film", kMaxFilmFrames));
    // Tolerate float noise: 10 s at 30 fps is 300 steps, not 301.
    moving_frames_ = static_cast<int>(std::ceil(steps - 1e-9)) + 1;
    frame_count_ = moving_frames_ + static_cast<int>(hold_frames);

    // Both ends on the path (throws InputError otherwise), before any file is touched.
    sim.frame(clip.from);
    sim.frame(clip.to);
    // An inset for a close view only, showing the whole clip's dragon in one view, as the
    // fitted camera does (which it becomes just below, hence the order).
    if (scene_.camera.mode != Camera::Mode::fit_dragon) {
        scene_.show_inset = scene_.show_inset || look_.inset;
        if (scene_.show_inset && !scene_.inset_camera) scene_.inset_camera = fit_over(sim, clip.from, clip.to);
    }
    if (scene_.camera.mode == Camera::Mode::fit_dragon)
        scene_.camera = fit_over(sim, clip.from, clip.to, scene_.camera.margin);
    if (scene_.colour_by_speed) {
        const SpeedRange r = speed_range_over(sim, clip.from, clip.to);
        if (!scene_.speed_min) scene_.speed_min = r.lo;
        if (!scene_.speed_max) scene_.speed_max = r.hi;
    }
    // A still camera shows one stretch of path for the whole clip, drawn once: from a turn
    // beyond the tail at its outermost to a dragon's length ahead of the head at its furthest.
    if (scene_.show_guides && scene_.camera.mode != Camera::Mode::follow_head && !scene_.guide_arcs)
        scene_.guide_arcs = guide_arcs_over(sim, clip.from, clip.to);
    backdrop_ = std::make_shared<render::BackdropCache>();
    scene_.show_legend = scene_.show_legend || look_.legend;
    // The clock tells the time: the annotation names what is shown instead.
    if (look_.clock && !scene_.annotation) scene_.annotation = scenario_line(sim.scenario(), scene_.language);
}

int Animation::frame_of(double t) const {
    const double steps = (t - clip_.from) * fps_ / clip_.speedup;
    return std::clamp(static_cast<int>(std::ceil(steps - 1e-9)), 0, moving_frames_ - 1);
}

double Animation::time_at(int index) const {
    if (index >= moving_frames_ - 1) return clip_.to;
    return clip_.from + index * clip_.speedup / fps_;
}

Scene Animation::scene_at(int index) const {
    const double t = time_at(index);
    SceneOptions opt = scene_;
    if (end_mark_ && t == clip_.to) opt.collision = end_mark_;
    Scene s = make_scene(*sim_, sim_->frame(t), opt);
    if (end_mark_) s.legend_touching = true;  // the legend keeps one set of entries for the clip
    if (look_.clock) {
        const render::Words& w = render::words(scene_.language);
        s.clock = fmt::format(fmt::runtime(w.clock), t);
        s.rate = index >= moving_frames_ ? std::string(w.held) : fmt::format("\u00d7{:g}", clip_.speedup);
    }
    // One caption at a time: the latest event's (a later one takes the place of an earlier).
    for (auto it = look_.events.rbegin(); it != look_.events.rend() && s.captions.empty(); ++it) {
        const FilmEvent& e = *it;
        if (e.time < clip_.from || e.time > clip_.to) continue;
        const int at = frame_of(e.time);
        const double since = (index - at) / fps_;  // s of film since the caption came up
        const bool last = at == moving_frames_ - 1;
        if (since < 0 || (!last && since >= look_.caption_seconds)) continue;
        // Half a second to fade out, unless it stays to the end.
        const double out = last ? 1.0 : std::clamp((look_.caption_seconds - since) / 0.5, 0.0, 1.0);
        s.captions.push_back({e.caption, out});
    }
    return s;
}

void Animation::paint(int index, cairo_t* cr, int width, int height) const {
    render::draw_reusing_backdrop(cr, scene_at(index), width, height, *backdrop_);
}

EncodeStats write_video(const Animation& anim, const std::string& path, VideoOptions opt,
                        const ProgressFn& progress) {
    opt.fps = anim.fps();
    const int w = opt.width, h = opt.height;
    // A followed view is furthest from the origin at an end of the clip (the head coils in,
    // or turns and coils out): the ends show whether every frame can be drawn.
    require_drawable(anim.scene_at(0), w, h);
    require_drawable(anim.scene_at(anim.distinct_frames() - 1), w, h);
    return encode_frames(path, opt, anim.frame_count(),
                         [&](int index, cairo_t* cr) { anim.paint(index, cr, w, h); }, progress,
                         anim.distinct_frames());
}

void require_zoom_resolves(const Animation& anim, int width_px, int height_px, double zoom) {
    for (const int index : {0, anim.distinct_frames() - 1}) require_zoom_resolves(anim.scene_at(index), width_px, height_px, zoom);
}

}  // namespace dragon
