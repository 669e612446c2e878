#include "dragon/look.hpp"

#include <cmath>

#include <fmt/format.h>

#include "dragon/language.hpp"

namespace dragon {

namespace {

// What pictures and clips share: theme, language, colours, guides and text.
SceneOptions common_options(const LookRequest& look, const std::string& asset_dir, RunOutputs* outputs) {
    SceneOptions so;
    so.theme = load_theme(look.theme, asset_dir, outputs);
    so.language = parse_language(look.lang);
    so.colour_by_speed = look.speed_colours;
    so.show_guides = so.show_turning_space = look.guides;
    so.show_text = look.text;
    so.text_px = look.text_px;
    if (look.zoom) check_zoom(*look.zoom);
    return so;
}

}  // namespace

void check_zoom(double zoom) {
    if (!(zoom >= kMinViewExtent && zoom <= kMaxViewExtent))
        throw InputError(Key::zoom, error_value(zoom),
                         fmt::format("give the view's width in metres, {:g}..{:g}", kMinViewExtent, kMaxViewExtent));
}

SceneOptions picture_scene_options(const LookRequest& look, const std::string& asset_dir, RunOutputs* outputs) {
    SceneOptions so = common_options(look, asset_dir, outputs);
    so.annotation = look.annotation;
    so.show_legend = look.legend;
    so.show_inset = look.inset;
    if (look.centre) {
        const Vec2 c = *look.centre;
        const std::string shown = fmt::format("{} {}", error_value(c.x()), error_value(c.y()));
        if (!look.zoom)
            throw InputError(Key::centre, shown, "a centre needs a zoom too (the view's width in metres)");
        if (!(std::abs(c.x()) <= kMaxViewCentre && std::abs(c.y()) <= kMaxViewCentre))
            throw InputError(Key::centre, shown,
                             fmt::format("give x y in metres, each within \u00b1{:g}", kMaxViewCentre));
        so.camera = Camera::at(c, *look.zoom);
    } else if (look.zoom) {
        so.camera = Camera::follow(*look.zoom);
    } else if (look.follow_head) {
        so.camera = Camera::follow(kFollowedPictureWidth);
    }
    return so;
}

SceneOptions clip_scene_options(const LookRequest& look, const std::string& asset_dir, RunOutputs* outputs) {
    if (look.centre)
        throw InputError(Key::centre, fmt::format("{} {}", error_value(look.centre->x()), error_value(look.centre->y())),
                         "a clip's view is fixed on the origin, or follows the head");
    SceneOptions so = common_options(look, asset_dir, outputs);
    if (look.follow_head) so.camera = Camera::follow(look.zoom.value_or(kFollowedClipWidth));
    else if (look.zoom) so.camera = Camera::at({0.0, 0.0}, *look.zoom);
    return so;
}

void require_zoom_resolves(const Scene& scene, int width_px, int height_px, double zoom) {
    const Vec2 c = scene.view_centre;
    if (check_view(c, scene.view_width, scene.view_height, width_px, height_px) == ViewError::none) return;
    throw InputError(Key::zoom, error_value(zoom),
                     fmt::format("doubles cannot resolve its pixels about ({:g}, {:g}) at {}x{} px; use a zoom of {:.3g} or more",
                                 c.x(), c.y(), width_px, height_px, narrowest_view(c, width_px, height_px)));
}

}  // namespace dragon
