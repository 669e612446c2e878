// The look-and-view flags of the drawing subcommands (render, figures): image size, theme,
// camera, speed colours. (--width is the board width among the scenario flags, so the image
// size is --size WxH.)
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "dragon/atomic_file.hpp"
#include "dragon/look.hpp"

namespace dragon::cli {

// --lang en|zh on `sub`, into `lang` (checked by parse_language: InputError "language").
void add_language_flag(CLI::App* sub, std::string& lang);

class RenderFlags {
public:
    void add_to(CLI::App* sub, bool with_view = true);
    // Size in pixels; throws InputError for a malformed --size.
    std::pair<int, int> size() const;
    // The look asked (the library checks it: dragon/look.hpp).
    LookRequest request() const;
    // Theme (a name looked up in `assets`, or a file), camera and switches (throws InputError
    // for a bad value); a theme file is one of the inputs of `outputs`' run.
    SceneOptions scene_options(const std::string& assets, RunOutputs* outputs) const;
    const std::string& theme_name() const { return theme_; }
    // --lang: the language of the words the picture carries by itself.
    Language language() const { return parse_language(lang_); }
    // --zoom: a square view of this many metres (around the contact with --collision).
    std::optional<double> zoom() const { return zoom_; }

private:
    std::string size_ = "1600x1600";
    std::string theme_ = "light";
    std::string lang_ = "en";
    std::optional<double> zoom_;
    std::vector<double> centre_;
    bool speed_colours_ = false, follow_head_ = false, no_guides_ = false, no_text_ = false;
    bool legend_ = false, inset_ = false;
    std::optional<std::string> annotation_;
};

}  // namespace dragon::cli
