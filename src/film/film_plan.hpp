// A storyboard resolved: per shot, its runs with every moment found, its frames and its timing.
// Built once by Film's constructor; read by every render thread (nothing in it changes after but
// the backdrop cache, which locks for itself).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "dragon/analyses.hpp"
#include "dragon/film.hpp"
#include "render/backdrop.hpp"
#include "time_map.hpp"

namespace dragon::film {

// A caption's stay within its shot, in the shot's frames [first, end).
struct CaptionSpan {
    std::string text;
    int first = 0, end = 0;
    bool to_the_end = false;  // stays to the shot's end (no fade)
};

// One scene of a shot, resolved.
struct ViewPlan {
    ShotView spec;
    std::shared_ptr<const Simulation> sim;
    double from = 0, to = 0;
    std::optional<CollisionMark> contact;  // the run's first contact, where a window or time needs it
    double contact_time = 0;               // s, when there is one
    bool ends_on_contact = false;          // `to` is that contact
    Camera fit;                            // the run's whole dragon over [from, to]
    // A still camera's one stretch of path for the shot (drawn once: render/backdrop.hpp);
    // unset for a camera that moves or follows the head.
    std::optional<std::pair<double, double>> guide_arcs;
    std::optional<SpeedRange> speeds;      // speed colours: one range for the shot
    TimeMap map{0, 1, 1};
    int moving = 1;                        // frames from `from` to `to` (the last shows `to`)
    std::vector<CaptionSpan> captions;     // in order of their first frame
};

struct ShotPlan {
    Shot shot;
    std::vector<ViewPlan> views;
    int count = 1;  // frames: the longest view's moving frames, then the freeze
    int moving = 1;
    int first = 0, fade = 0;  // place in the film; frames fading in over the shot before
};

}  // namespace dragon::film

namespace dragon {

struct Film::Impl {
    FilmSettings settings;
    Theme theme;
    std::vector<film::ShotPlan> shots;
    std::vector<ShotSpan> spans;
    int frames = 0;
    std::string file;
    // The still shots' backdrops, drawn once (render/backdrop.hpp); shared by the render threads.
    std::shared_ptr<render::BackdropCache> backdrop = std::make_shared<render::BackdropCache>();
};

}  // namespace dragon
