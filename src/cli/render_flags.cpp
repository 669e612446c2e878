#include "render_flags.hpp"

#include <fmt/format.h>

#include "dragon/picture_size.hpp"
#include "dragon/scenario.hpp"

namespace dragon::cli {

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

LookRequest RenderFlags::request() const {
    LookRequest look;
    look.theme = theme_;
    look.lang = lang_;
    look.speed_colours = speed_colours_;
    look.guides = !no_guides_;
    look.text = !no_text_;
    look.annotation = annotation_;
    look.legend = legend_;
    look.inset = inset_;
    look.zoom = zoom_;
    if (centre_.size() == 2) look.centre = Vec2(centre_[0], centre_[1]);
    look.follow_head = follow_head_;
    return look;
}

SceneOptions RenderFlags::scene_options(const std::string& assets, RunOutputs* outputs) const {
    return picture_scene_options(request(), assets, outputs);
}

}  // namespace dragon::cli
