#include "asset_dir.hpp"
#include "render_flags.hpp"

#include <cmath>

#include <fmt/format.h>

#include "dragon/picture_size.hpp"
#include "dragon/scenario.hpp"

namespace dragon::cli {

void check_zoom(double zoom) {
    if (!(zoom >= kMinViewExtent && zoom <= kMaxViewExtent))
        throw InputError(fmt::format("--zoom {} is not allowed: give the view's width in metres, {:g}..{:g}", zoom,
                                     kMinViewExtent, kMaxViewExtent));
}

void require_zoom_resolves(const Scene& scene, int w, int h, double zoom) {
    const Vec2 c = scene.view_centre;
    if (check_view(c, scene.view_width, scene.view_height, w, h) == ViewError::none) return;
    throw InputError(fmt::format("--zoom {} is not allowed about ({:g}, {:g}) at {}x{} px: doubles cannot resolve "
                                 "its pixels there; use --zoom {:.3g} or more",
                                 zoom, c.x(), c.y(), w, h, narrowest_view(c, w, h)));
}

void add_language_flag(CLI::App* sub, std::string& lang) {
    sub->add_option("--lang", lang, "Language of the words drawn: en (default) or zh (Chinese: 龙头, 龙身, 龙尾, 把手, "
                                    "螺距, 调头空间; text you give is drawn as given)");
}

void RenderFlags::add_to(CLI::App* sub, bool with_view) {
    sub->add_option("--size", size_, "Image size in pixels, WxH (default 1600x1600)");
    sub->add_option("--theme", theme_, "Colour theme: light, dark or a .toml file (default light)");
    add_language_flag(sub, lang_);
    if (!with_view) return;
    sub->add_flag("--speed-colours", speed_colours_, "Colour each bench by its speed, with a colour bar");
    sub->add_option("--zoom", zoom_,
                    "Show a square of this many metres, 1e-9..1e8 (around the head, the --centre or the contact)");
    sub->add_option("--centre", centre_, "Centre of the view, x y in metres (with --zoom)")->expected(2);
    sub->add_flag("--follow-head", follow_head_, "Centre the view on the head (with --zoom)");
    sub->add_flag("--no-guides", no_guides_, "Leave out the path and the turning-space circle");
    sub->add_flag("--no-text", no_text_, "Leave out all text");
    sub->add_option("--annotation", annotation_, "Text at the top left (default: time and pitch)");
    sub->add_flag("--legend", legend_, "A key to the colours (head, body, tail, touching benches, path)");
    sub->add_flag("--inset", inset_, "With --zoom: the whole dragon small in a corner, the view marked on it");
}

std::pair<int, int> RenderFlags::size() const {
    const PictureSize size = parse_picture_size(size_);
    return {size.width, size.height};
}

SceneOptions RenderFlags::scene_options(RunOutputs* outputs) const {
    SceneOptions so;
    so.theme = load_theme(theme_, asset_dir(), outputs);
    so.colour_by_speed = speed_colours_;
    so.show_guides = so.show_turning_space = !no_guides_;
    so.show_text = !no_text_;
    so.annotation = annotation_;
    so.show_legend = legend_;
    so.show_inset = inset_;
    so.language = language();
    if (zoom_) check_zoom(*zoom_);
    if (!centre_.empty() && !zoom_) throw InputError("--centre needs --zoom (the width of the view in metres)");
    for (double c : centre_)
        if (!(std::abs(c) <= kMaxViewCentre))
            throw InputError(fmt::format("--centre {} {} is not allowed: give x y in metres, each within \u00b1{:g}",
                                         centre_[0], centre_[1], kMaxViewCentre));
    if (zoom_) {
        if (!centre_.empty()) so.camera = Camera::at({centre_[0], centre_[1]}, *zoom_);
        else so.camera = Camera::follow(*zoom_);
    }
    if (follow_head_ && !zoom_) so.camera = Camera::follow(20.0);
    return so;
}

}  // namespace dragon::cli
