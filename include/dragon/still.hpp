// One moment drawn as the render command draws it (the tool and the Python package share it):
// at a time the motion reaches, or at the motion's first contact with the touching benches
// marked. Past the first contact the default annotation says so.
#pragma once

#include <optional>

#include "dragon/analyses.hpp"
#include "dragon/chain.hpp"
#include "dragon/render.hpp"

namespace dragon {

// One moment drawn: the chain then, and the scene that draws it.
struct Still {
    Frame frame;  // the chain at the moment drawn
    Scene scene;  // make_scene's, ready for draw() or a render_* writer
};

// The chain at time t (s). Throws InputError (field `time_field`) unless the valid motion
// reaches t, and as make_scene does for a bad camera. An unset annotation becomes the time and
// pitch, with the first contact when t is past it, in the scene's language. Either way the
// annotation gets a band of its own above the view (SceneOptions::title_band), hiding nothing.
Still still_at(const Simulation& sim, double t, SceneOptions so, Key time_field = Key::time);

// The chain at the motion's first contact (first_contact_of_motion: the one every command
// reports), the touching benches and their meeting point marked and the benches named ("bench 1
// (head)", "bench 9": SceneOptions::name_touching), the view `zoom` metres wide
// about that point when given. Unset when no two benches touch in the motion's default window:
// `searched` then says what was searched and where the motion ends. Throws as make_scene does.
std::optional<Still> still_at_first_contact(const Simulation& sim, SceneOptions so, std::optional<double> zoom,
                                            CollideAnswer* searched = nullptr);

}  // namespace dragon
