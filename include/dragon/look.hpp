// How a picture or a clip looks and what part of the plane it shows, as a user asks it: the
// render and video commands' look flags, Python's keywords and the page's controls all map onto
// a LookRequest, and its rules (a zoom's range, a centre only with a zoom, how a followed head
// is framed, whether doubles resolve the view's pixels) are kept here once.
#pragma once

#include <optional>
#include <string>

#include "dragon/geometry.hpp"
#include "dragon/render.hpp"

namespace dragon {

class RunOutputs;  // dragon/atomic_file.hpp (the io component)

// A look, as asked. Unset values keep SceneOptions' defaults.
struct LookRequest {
    std::string theme = "light";  // light, dark, or a .toml file
    std::string lang = "en";      // the words the picture carries by itself: en or zh
    bool speed_colours = false;   // each bench coloured by its speed, with a colour bar
    bool guides = true;           // the path and the turning-space circle
    bool text = true;             // any text at all
    std::optional<std::string> annotation;  // the top-left text (default: time and pitch)
    bool legend = false;          // a key to the colours
    bool inset = false;           // with a zoom: the whole dragon small in a corner
    std::optional<double> zoom;   // a square view this many metres wide (Key::zoom)
    std::optional<Vec2> centre;   // the view's centre, metres (Key::centre; only with a zoom)
    bool follow_head = false;     // the view centred on the head
    double text_px = 0;           // the body text's size in pixels (0: from the picture's size)
};

// How wide a followed head's view is when no zoom is given: a picture shows the head's
// neighbourhood a few benches around; a clip, whose head moves on while the picture holds, a
// closer square, since every frame is about the head.
inline constexpr double kFollowedPictureWidth = 20.0;  // m
inline constexpr double kFollowedClipWidth = 12.0;     // m

// Throws InputError (Key::zoom) unless kMinViewExtent <= zoom <= kMaxViewExtent.
void check_zoom(double zoom);

// A picture's scene options (dragon render, Python's render): the theme loaded from
// `asset_dir` (see find_asset_dir), the camera at `centre` when given, else following the head
// at `zoom` metres when a zoom is given (the contact's picture centres it on the contact
// instead), else following the head at kFollowedPictureWidth with follow_head, else the whole
// dragon. Throws InputError naming the key: a zoom out of range, a centre without a zoom or
// beyond kMaxViewCentre, an unknown theme or language.
// A theme file is one of the inputs of `outputs`' run (when given).
SceneOptions picture_scene_options(const LookRequest& look, const std::string& asset_dir, RunOutputs* outputs = nullptr);

// A clip's scene options (dragon video, Python's video): as a picture's, but the camera is
// fixed on the origin at `zoom` metres, or follows the head at `zoom` (kFollowedClipWidth
// without one) with follow_head. A centre is refused (Key::centre): a clip's view is the
// origin's or the head's. The annotation, legend and inset are the clip's own (FilmLook).
SceneOptions clip_scene_options(const LookRequest& look, const std::string& asset_dir, RunOutputs* outputs = nullptr);

// A zoomed view, at this picture size, whose pixels doubles cannot resolve (check_view's
// too_fine, far from the origin) is refused: InputError (Key::zoom) naming the centre and the
// narrowest zoom allowed there. Nothing for a view that resolves.
void require_zoom_resolves(const Scene& scene, int width_px, int height_px, double zoom);

}  // namespace dragon
