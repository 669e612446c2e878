// One moment drawn as the render command draws it (the tool and the Python package share it):
// at a time the motion reaches, or at the motion's first contact with the touching benches
// marked. Past the first contact the default annotation says so.
#pragma once

#include <optional>

#include "dragon/analyses.hpp"
#include "dragon/chain.hpp"
#include "dragon/render.hpp"

namespace dragon {

struct Still {
    Frame frame;
    Scene scene;
};

// The chain at time t (s). Throws InputError (field `time_field`) unless the valid motion
// reaches t, and as make_scene does for a bad camera. An unset annotation becomes the time and
// pitch, with the first contact when t is past it.
Still still_at(const Simulation& sim, double t, SceneOptions so, const char* time_field = "time");

// The chain at the motion's first contact (first_contact_of_motion: the one every command
// reports), the touching benches and their meeting point marked, the view `zoom` metres wide
// about that point when given. Unset when no two benches touch in the motion's default window:
// `searched` then says what was searched and where the motion ends. Throws as make_scene does.
std::optional<Still> still_at_first_contact(const Simulation& sim, SceneOptions so, std::optional<double> zoom,
                                            CollideAnswer* searched = nullptr);

}  // namespace dragon
