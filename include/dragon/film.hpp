// Storyboards: one TOML file, one film. A storyboard is data: shots, each a stretch of one
// scenario's motion (or two side by side, or a title card) with a playback rate, a camera,
// captions and a transition from the shot before. It is read and checked here, resolved
// against its simulations (the first contact, the turning space, the end of the valid motion)
// and rendered frame by frame on demand through the video writer, so memory stays at a few
// frames whatever the film's length. The format is described in docs/storyboards.md.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <cairo.h>

#include "dragon/render.hpp"
#include "dragon/scenario.hpp"
#include "dragon/video.hpp"

namespace dragon {

// A bad storyboard, naming where: the shot (1-based; 0: the [film] table) and the key.
struct StoryboardError : InputError {
    // The message names the file, the shot (by `shot_name`), the key and `why`.
    StoryboardError(const std::string& file, int shot, const std::string& shot_name, const std::string& key,
                    const std::string& why);
    int shot = 0;     // 1-based; 0: the [film] table
    std::string key;  // as the storyboard spells it ("split[2].to")
};

// A moment of a shot's run: a time, a head travel ("-100 m": the head 100 m before its place at
// t = 0; the default runs are travel, so a shot shows the same dragon at any head speed), or an
// event of the run plus an offset ("collision - 5": five simulated seconds before the first
// contact).
struct TimeRef {
    // What the moment is measured from: t = 0 (time), the head's place at t = 0 (travel), the
    // run's first contact, the head reaching the turning space's boundary, the end of the valid
    // motion.
    enum class Anchor { time, travel, collision, boundary, end };
    Anchor anchor = Anchor::time;  // what `offset` counts from
    double offset = 0.0;  // s; the time itself for Anchor::time, the travel (m) for Anchor::travel
};

// What a camera shows: the run's whole dragon, the head (followed), a fixed window, or a
// window about the run's first contact.
struct Window {
    // The four views above, in that order.
    enum class Kind { fit, head, fixed, contact };
    Kind kind = Kind::fit;  // which
    Vec2 centre = Vec2::Zero();  // fixed
    double extent = 0.0;  // head, fixed, contact: metres across
};

// How a camera moves between its windows: at a steady pace, or starting and stopping gently.
enum class Ease { linear, in_out };

// A camera that stays (from only) or moves from one window to another over the shot.
struct CameraMove {
    Window from;               // at the shot's start
    std::optional<Window> to;  // at its end; unset: the camera stays
    Ease ease = Ease::in_out;  // how it moves
};

// Slower playback near a moment: `rate` simulated seconds per film second within `within`
// simulated seconds of `at`, easing back to the shot's rate over as long again on each side.
struct SlowMotion {
    TimeRef at;           // the moment slowed about
    double within = 0.0;  // simulated s either side of it
    double rate = 1.0;    // simulated s per film s there
};

// The shot's last moment held for `seconds` of film, the camera closing in on a window `zoom`
// metres across about the contact (or the head, when the shot does not end on one).
struct Freeze {
    double seconds = 0.0;        // film s; 0: no freeze
    std::optional<double> zoom;  // m across; unset: the view stays
};

// A caption of the storyboard's own, from `at` (the shot's start if unset) for `seconds` of film.
struct CaptionSpec {
    std::string text;           // the words
    std::optional<TimeRef> at;  // from when
    double seconds = 3.0;       // for how long, film s
};

// One scene: a scenario on its path over [from, to], seen through a camera.
struct ShotView {
    Scenario scenario;  // checked (validate) when read
    // The scene's annotation (top left); unset: the scenario in words; empty: none.
    std::optional<std::string> label;
    TimeRef from;                 // where the scene starts (a storyboard's default: head travel 0, or -100 m on the turnaround)
    TimeRef to;                   // where it ends (the default: the first contact, or +100 m on the turnaround)
    CameraMove camera;            // what the camera shows
    bool speed_colours = false;   // benches coloured by speed, with a colour bar
    bool guides = true;           // the path drawn under the dragon
};

// One shot of a film: a scene, two scenes side by side, or a title card.
struct Shot {
    // A scene, two side by side, or a title card.
    enum class Kind { scene, split, title };
    Kind kind = Kind::scene;  // which
    std::string name;                 // for messages: the shot's name key, or "shot N"
    std::string title;                // a title card's title
    std::string subtitle;             // and its subtitle
    std::vector<ShotView> views;      // one (scene) or two side by side (split)
    std::optional<double> rate;       // simulated s per film s
    std::optional<double> duration;   // film s (a title card's, or a scene's instead of a rate)
    std::optional<SlowMotion> slow;   // slower near a moment
    Freeze freeze;                    // the last moment held
    std::vector<CaptionSpec> captions;  // the storyboard's own captions
    bool events = true;               // captions at the run's events (turning space, contact, end)
    bool legend = true;               // what the colours mean
    bool clock = true;                // the simulated time and the playback rate
    bool inset = true;                // the whole dragon small, on a close view
    bool text = true;                 // false: no words at all (clean footage)
    double crossfade = 0.0;           // film s over which it fades in over the shot before; 0: a cut
};

// The whole film's settings: the storyboard's [film] table.
struct FilmSettings {
    int width = 1280;              // px
    int height = 720;              // px
    double fps = 30.0;             // frames a second
    std::string theme = "light";   // a theme's name or .toml file (load_theme)
    // The language of the film's own words (the clock's, the events' captions, the scenario in
    // words, the legend); a storyboard's `lang` key.
    Language language = Language::en;
    // The body text's size, px, for frames at a print size (a poster for a paper: Scene::text_px);
    // 0: text follows the frame's size.
    double text_px = 0.0;
};

// What a storyboard may hold, so that reading and drawing it stay bounded whatever the file
// says (a million one-line shots took 1 GB for one frame; a 5 MB title, 19 s a frame): shots,
// characters in any one text (a title, a caption, a label), captions per shot. A frame shows
// at most its title and subtitle, or its label and its shot's captions: a few thousand
// characters.
inline constexpr std::size_t kMaxStoryboardShots = 1000;
inline constexpr std::size_t kMaxStoryboardText = 500;
inline constexpr std::size_t kMaxShotCaptions = 20;

// A storyboard as read and checked: the film's settings and its shots.
struct Storyboard {
    std::string file;  // for messages
    std::string asset_dir;  // where its presets and named themes were looked for
    FilmSettings film;       // the [film] table
    std::vector<Shot> shots;  // in film order
    // One per old name in a scenario file its shots name (each file read once), in the order read.
    KeyWarnings warnings;
};

// Reads a storyboard: unknown keys, wrong types, values out of range and more than the limits
// above are StoryboardErrors naming the shot and key. A shot's scenario is a preset's name (assets/<name>.toml) or a
// .toml file relative to the storyboard, with the shot's own keys over it. Times are checked
// against the runs by Film. Given a RunOutputs, the storyboard and the scenario files it names
// are inputs of that run (dragon/atomic_file.hpp), which none of its outputs may be.
Storyboard load_storyboard(const std::string& path, const std::string& asset_dir = "", RunOutputs* outputs = nullptr);
// The same from the file's text: `file` names it in messages, files it names are relative to
// `base_dir`.
Storyboard parse_storyboard(const std::string& toml_text, const std::string& file, const std::string& base_dir,
                            const std::string& asset_dir = "", RunOutputs* outputs = nullptr);

// A storyboard resolved against its simulations: every time found (first contacts searched,
// the turning space and the end of the valid motion located), every frame's moment and camera
// known, nothing drawn. Throws StoryboardError for a moment past the valid motion (or off the
// path), an empty or reversed range, a contact that never happens, or transitions that
// overlap.
class Film {
public:
    // Throws as above. Given a RunOutputs, a theme file the film names is one of its inputs.
    explicit Film(const Storyboard& board, RunOutputs* outputs = nullptr);
    ~Film();
    Film(const Film&) = delete;
    Film& operator=(const Film&) = delete;

    const FilmSettings& settings() const;  // the storyboard's
    int frame_count() const;               // every shot's frames, crossfades counted once
    double duration() const { return frame_count() / settings().fps; }  // s

    // Where each shot lies in the film: its first frame, its frame count and how many of its
    // first frames fade in over the shot before.
    struct ShotSpan {
        int first = 0;  // the film frame it starts on
        int count = 0;  // its frames
        int fade = 0;   // its first frames that fade in over the shot before
    };
    const std::vector<ShotSpan>& spans() const;  // one per shot, in order
    // The simulated moment frame `local` of shot `shot` shows in its view `view`.
    double time_at(int shot, int local, int view = 0) const;
    // The scene of that frame (its camera, captions, clock), as paint() draws it.
    Scene scene_at(int shot, int local, int view = 0) const;

    // Paints film frame `index` onto a width x height picture; safe to call from several threads.
    void paint(int index, cairo_t* cr) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// Renders and encodes the film (opt's size and rate are the film's).
EncodeStats write_film(const Film& film, const std::string& path, VideoOptions opt, const ProgressFn& progress = {});
// One frame, the one shown `at` seconds into the film, as a PNG (all-or-nothing), stating `dpi`
// as its resolution when > 0 (a poster at a print size). A moment outside the film is an
// InputError ("film moment").
void write_film_frame(const Film& film, double at, const std::string& path, double dpi = 0,
                      RunOutputs* outputs = nullptr);

}  // namespace dragon
