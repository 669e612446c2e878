// Drawing the dragon with Cairo. make_scene turns a simulated moment into a display list in
// world coordinates (metres); draw() paints it onto any Cairo context. PNG, SVG and video
// frames differ only in the surface.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <cairo.h>

#include "dragon/chain.hpp"
#include "dragon/collision.hpp"
#include "dragon/geometry.hpp"
#include "dragon/language.hpp"
#include "dragon/picture_size.hpp"

namespace dragon {

class RunOutputs;  // dragon/atomic_file.hpp (io): the run a file written below belongs to, if given

// A colour, components in [0, 1] (straight, not premultiplied).
struct Rgba {
    double r = 0;  // red
    double g = 0;  // green
    double b = 0;  // blue
    double a = 1;  // opacity: 0 clear, 1 opaque
};

// Colours and type of a picture. The defaults are the light theme, so a Theme{} is usable
// without any asset file.
struct Theme {
    std::string name = "light";        // as load_theme was given it
    std::string font = "DejaVu Sans";  // the text's family (characters it lacks come from a CJK fallback)
    Rgba background{1, 1, 1};          // the picture's ground
    Rgba text{0.13, 0.13, 0.15};       // every word and number
    Rgba grid{0.85, 0.86, 0.88};       // plots' grid lines and frames
    Rgba guide{0.62, 0.66, 0.72};          // the coil-in spiral
    Rgba guide_out{0.55, 0.70, 0.62};      // the coil-out spiral (turnaround path)
    Rgba s_curve{0.80, 0.45, 0.10};        // the two arcs of the turnaround
    Rgba turning_space{0.35, 0.55, 0.85};  // outline of the turning-space disk
    Rgba turning_fill{0.35, 0.55, 0.85, 0.07};  // inside the turning-space disk
    Rgba head{0.80, 0.16, 0.16};       // bench 1
    Rgba body{0.96, 0.72, 0.30};       // benches 2 .. N - 1
    Rgba tail{0.30, 0.45, 0.75};       // bench N
    Rgba outline{0.25, 0.18, 0.10};    // every bench's edge
    Rgba handle{0.12, 0.12, 0.14};     // the handles' dots
    Rgba highlight{0.55, 0.30, 0.85};      // benches singled out (e.g. the broad phase's picks)
    Rgba collision{0.90, 0.05, 0.35};      // the touching benches
    Rgba contact{0.05, 0.05, 0.05};        // the contact point marker
    // Colour map for speeds, low to high, evenly spaced stops (at least two).
    std::vector<Rgba> speed_ramp{{0.27, 0.00, 0.33}, {0.23, 0.32, 0.55}, {0.13, 0.57, 0.55},
                                 {0.37, 0.79, 0.38}, {0.99, 0.91, 0.14}};
};

// Where to find assets (themes, scenarios): `hint` if not empty, else the install dir
// (<prefix>/share/benchdragon). The library reads no environment variable: a front end that
// offers one ($DRAGON_ASSETS for the dragon tool) passes its folder as the hint. Throws
// FileError (naming the folders tried) if none holds a themes/ folder.
std::string find_asset_dir(const std::string& hint = "");
// "light", "dark" (assets/themes/<name>.toml) or a path to a .toml file. Keys missing from the
// file keep the light theme's values. Throws InputError for an unknown name or a bad file.
Theme load_theme(const std::string& name_or_path, const std::string& asset_dir = "", RunOutputs* outputs = nullptr);

// What part of the plane the picture shows. The view keeps the aspect ratio: the given extent
// fits inside the image along both directions (y up, metres).
struct Camera {
    // What the camera keeps in view.
    enum class Mode {
        fit_dragon,   // the bounding box of all benches, plus a margin
        fixed,        // centre and extent as given
        follow_head,  // centred on the head front handle, extent as given
    };
    Mode mode = Mode::fit_dragon;  // which of the three
    Vec2 centre = Vec2::Zero();  // fixed mode
    double extent = 0.0;  // fixed / follow_head: width and height of the square that must fit, m
    double margin = 0.04; // fit_dragon: fraction of the box added on every side

    static Camera fit() { return {}; }  // the whole dragon
    // A fixed view about c (m), extent_m metres across.
    static Camera at(const Vec2& c, double extent_m) { return {Mode::fixed, c, extent_m}; }
    // A view following the head, extent_m metres across.
    static Camera follow(double extent_m) { return {Mode::follow_head, Vec2::Zero(), extent_m}; }
};

// The views a picture can mean. Narrower than kMinViewExtent, or with pixels finer than
// kMinPixelOverRadius of the view's distance from the origin (about 4,500 units in the last
// place of a coordinate there), a picture would show rounding, not the dragon; wider than
// kMaxViewExtent or centred further out than kMaxViewCentre, it would show none of any path
// (every handle stays within kMaxReach = 1e7 m of the centre).
inline constexpr double kMinViewExtent = 1e-9;        // m
inline constexpr double kMaxViewExtent = 1e8;         // m
inline constexpr double kMaxViewCentre = 1e8;         // m, each coordinate
inline constexpr double kMinPixelOverRadius = 1e-12;  // pixel size over the view's distance from the origin

// What check_view finds wrong with a view, if anything (in the order of the paragraph above:
// not finite; narrower than kMinViewExtent; wider than kMaxViewExtent; centred beyond
// kMaxViewCentre; pixels finer than kMinPixelOverRadius allows).
enum class ViewError { none, not_finite, too_narrow, too_wide, too_far, too_fine };
// What is wrong with a view of view_width x view_height metres about `centre`, drawn on
// width_px x height_px pixels (the view fits inside, aspect ratio kept).
ViewError check_view(const Vec2& centre, double view_width, double view_height, int width_px, int height_px);
// The narrowest square view about `centre` that check_view takes at this size, m.
double narrowest_view(const Vec2& centre, int width_px, int height_px);

// Two benches that touch and where (from first_contact / clearance).
struct CollisionMark {
    int bench_a = 0;            // 1..N
    int bench_b = 0;            // 1..N
    Vec2 point = Vec2::Zero();  // where they touch, m
};

// What make_scene draws and how: the camera, the colours and what the picture carries.
struct SceneOptions {
    Camera camera;                  // the view
    Theme theme;                    // the colours and type
    bool colour_by_speed = false;   // benches coloured by their speed (with a colour bar)
    // Speed range of the colour map, m/s; unset: the frame's own minimum and maximum.
    std::optional<double> speed_min;
    std::optional<double> speed_max;  // m/s; unset: the frame's own maximum
    bool show_guides = true;         // the path: spiral(s) and S-curve
    bool show_turning_space = true;  // the turning-space circle
    bool show_handles = true;        // the handles' dots
    bool show_scale_bar = true;      // a bar of a round number of metres
    bool show_colour_bar = true;     // only drawn when colouring by speed
    // All text (annotation, scale-bar and colour-bar labels). Golden tests switch it off.
    bool show_text = true;
    // Top-left annotation. Unset: "t = 300.000 s   pitch = 0.55 m" from the frame and scenario;
    // an empty string: none.
    std::optional<std::string> annotation;
    // The annotation gets a band of its own and the view fits below it (figures: a title must
    // hide nothing); otherwise it lies over the drawing (films: the view stays put).
    bool title_band = false;
    // A key to the colours: head, body, tail, touching benches, the path and the turning space
    // (the colour bar carries the speeds and their unit).
    bool show_legend = false;
    // A small picture of the whole dragon in a corner, the view marked on it: for a camera that
    // follows the head or shows a fixed window (none on fit_dragon: it would repeat the picture).
    bool show_inset = false;
    // The inset's view; unset: the frame's whole dragon (a film fixes one for the clip).
    std::optional<Camera> inset_camera;
    std::optional<CollisionMark> collision;  // two touching benches to mark, and where
    std::vector<int> highlight_benches;  // drawn in the theme's highlight colour
    // Benches lying across each other (past the first contact the chain overlaps itself): drawn
    // in the touching colour, each overlap's deepest corner marked, the deepest labelled with
    // its depth. Overlaps under kTouchingDepth are touching, not crossing, and left as drawn.
    bool mark_overlaps = true;
    // Scene::text_px: the body text's size for a picture at a print size, px; 0 on screen.
    double text_px = 0.0;
    // The language of the words the picture carries by itself: the legend, the colour bar's
    // title, the default annotation, the overlap's label, the touching benches' names.
    Language language = Language::en;
    // Name the touching benches of `collision` on the picture ("bench 1 (head)", "bench 9"), so
    // a reader knows which is the head without the legend.
    bool name_touching = false;
    // The stretch of the path drawn as the guide, arc length from .. to, m, drawn whole. Unset:
    // guide_arcs_of(frame), less the parts lying under the benches (which would only cost time).
    // A film with a still camera sets one stretch for the whole clip: the path stays put while
    // the dragon moves along it, and is drawn once (the frames after the first copy it).
    std::optional<std::pair<double, double>> guide_arcs;
};
inline constexpr double kTouchingDepth = 1e-6;  // m

// The stretch of the path a frame's guide covers, arc length from .. to, m: from a turn beyond
// the tail to a dragon's length ahead of the head (to the centre on the plain spiral).
std::pair<double, double> guide_arcs_of(const Simulation& sim, const Frame& frame);

// Overlays figures add on top of the dragon (world coordinates; sizes in pixels at 800 px,
// scaled with the image).
struct Polyline {
    std::vector<Vec2> points;  // m
    Rgba colour;               // the line's
    double width_px = 1.5;     // the line's width
    bool dashed = false;       // dashed, else solid
    bool closed = false;       // back to the first point
    bool arrow = false;  // an arrowhead at the last point
};
// A dot (or ring) at a point.
struct Marker {
    Vec2 pos = Vec2::Zero();  // m
    Rgba colour;              // its colour
    double radius_px = 4.0;   // its radius
    bool ring = false;  // an open circle instead of a dot
};
// A label names a point. draw() places it by one rule rather than by its offset alone: the
// place nearest the preferred one (the text's baseline starting (dx, dy) pixels from `pos`)
// where it lies inside the picture, clear of the other labels, of the screen furniture, of
// the lines drawn and of every bench but the one it names; a label set away from its point
// gets a leader line to it.
struct Label {
    Vec2 pos = Vec2::Zero();  // the point it names, m
    std::string text;         // the words
    Rgba colour;              // the text's
    double size_px = 13.0;    // the text's size
    double dx_px = 4.0;       // the preferred offset of the text's baseline start, right
    double dy_px = -4.0;      // and down (negative: up)
    int bench = 0;    // the first bench (1..N) the label names, which it may cover; 0: none
    int benches = 1;  // how many benches from `bench` on it names (a handle's number: the two it joins)
};

// A display list: everything draw() needs, already resolved (no solver calls while drawing;
// only the guides' path is evaluated, over the part of it in the picture).
struct Scene {
    // Which of the theme's colours a bench is drawn in.
    enum class Style { head, body, tail, highlight, collision };
    // One bench as drawn.
    struct Bench {
        Rect rect;      // its board, m
        Style style;    // its colour
        double speed;  // mean of its two handles, m/s
    };
    // A stretch of the path, drawn as a thin line. draw() flattens it into Bezier curves only
    // where the picture shows it, so a close-up of a long path costs what it shows.
    struct Guide {
        std::shared_ptr<const Path> path;  // the path it is a stretch of
        double s0 = 0.0;                   // arc range on one piece of the path, m: from
        double s1 = 0.0;                   // to
        Rgba colour;                       // the line's
        double width_px = 1.0;             // the line's width
        bool dashed = false;               // dashed, else solid
    };

    Theme theme;  // the colours and type
    // The view: world box that must fit (centre, extent in x and y).
    Vec2 view_centre = Vec2::Zero();
    double view_width = 1.0;   // m
    double view_height = 1.0;  // m

    std::vector<Bench> benches;  // bench k at index k-1
    std::vector<Vec2> handles;   // m, head front first
    double handle_radius = 0.0275;  // m (hole radius); drawn at least ~1 px
    std::vector<Guide> guides;   // the path, under the benches
    std::optional<double> turning_radius;  // circle about the origin, m
    std::optional<CollisionMark> collision;  // the touching benches, marked
    std::vector<Overlap> overlaps;  // benches lying across each other, deepest first

    bool colour_by_speed = false;  // benches in the speed ramp's colours
    double speed_min = 0.0;        // m/s at the ramp's low end
    double speed_max = 1.0;        // m/s at its high end
    bool show_handles = true;      // SceneOptions::show_handles
    bool show_scale_bar = true;    // SceneOptions::show_scale_bar
    bool show_colour_bar = true;   // SceneOptions::show_colour_bar
    bool show_text = true;         // SceneOptions::show_text
    std::string annotation;        // top left; empty: none
    bool title_band = false;  // SceneOptions::title_band
    // The size of the body text (labels, legend, scale bar, colour-bar numbers), px, for a
    // picture at a print size: titles, captions and the clock are a fifth larger, and lines and
    // gaps follow the text. 0: every size follows the picture's (kMinTextPx at least).
    double text_px = 0.0;
    Language language = Language::en;  // SceneOptions::language: the legend's and colour bar's words

    // Screen furniture (films mostly). Text is set at a size that follows the picture's height
    // but never below kMinTextPx, so it reads on a 400 x 300 GIF as on a 4K frame.
    bool legend = false;           // a key to the colours, top left
    bool legend_touching = false;  // the legend has an entry for touching benches
    std::string clock;             // top right, e.g. "t = 412.474 s"
    std::string rate;              // under the clock, e.g. "×20": simulated seconds per second of film
    // A caption at the bottom of the picture.
    struct Caption {
        std::string text;      // the words
        double opacity = 1.0;  // captions fade in and out
    };
    std::vector<Caption> captions;  // bottom centre, one box each, the last lowest
    // The whole dragon, drawn small in the bottom right corner with the main view's box on it.
    std::shared_ptr<const Scene> inset;

    std::vector<Polyline> polylines;  // a figure's overlays, over the benches
    std::vector<Marker> markers;      // over the lines
    std::vector<Label> labels;        // over everything, placed clear of each other
};

// The smallest text any picture sets, px: the size a 13 px label has at 800 px keeps to at
// least this on smaller pictures.
inline constexpr double kMinTextPx = 11.0;

// Throws InputError for a fixed or followed camera whose extent is outside kMinViewExtent ..
// kMaxViewExtent or whose centre is not finite or beyond kMaxViewCentre.
Scene make_scene(const Simulation& sim, const Frame& frame, const SceneOptions& opt);

// Paints the scene over the whole width_px x height_px area of `cr` (its current transform is
// taken as device pixels), starting with an opaque background. Leaves cr's state unchanged.
void draw(cairo_t* cr, const Scene& scene, int width_px, int height_px);

// Throws InputError, naming the view and what is allowed, unless check_view takes the scene's
// view at this size.
void require_drawable(const Scene& scene, int width_px, int height_px);

// Whole files, written all-or-nothing (AtomicFile). Throw InputError for a bad size or path or
// a view require_drawable refuses, std::runtime_error if Cairo fails. A PNG states the page's
// resolution when it has one.
void render_png(const Scene& scene, int width_px, int height_px, const std::string& path, const Page& page = {},
                RunOutputs* outputs = nullptr);
// SVG in px as asked; PDF in points at 96 px to the inch (1600 px: 1200 pt), fonts embedded
// and text selectable; with a page, both exactly the page's size in points.
void render_svg(const Scene& scene, int width_px, int height_px, const std::string& path, const Page& page = {},
                RunOutputs* outputs = nullptr);
/// The PDF of the scene (as render_svg: points at 96 px to the inch, or the page's size).
void render_pdf(const Scene& scene, int width_px, int height_px, const std::string& path, const Page& page = {},
                RunOutputs* outputs = nullptr);
// The scene at a print size (its width on the page, its text in points; aspect: height over
// width), in the format of the path's extension (.png at size.dpi, .svg, .pdf). Throws as
// print_layout and the writers above do.
void render_print(Scene scene, const PrintSize& size, double aspect, const std::string& path,
                  RunOutputs* outputs = nullptr);

}  // namespace dragon
