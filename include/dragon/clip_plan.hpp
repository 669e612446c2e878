// A film of one scenario's motion as asked in words, as the video command asks for it: where
// it starts and ends (a time, head travel, or one of the motion's events), how fast it plays
// and how long it holds its last moment. The tool and the Python package plan their clips
// here, so a clip asked the same way is the same clip.
#pragma once

#include <optional>
#include <string>

#include "dragon/video.hpp"

namespace dragon {

struct ClipRequest {
    // "12.5", "12.5s": simulated seconds; "-100m": head travel. Unset: 0 on the plain spiral,
    // 100 m of head travel before the turn on the turnaround path.
    std::optional<std::string> from;
    // As `from`, or "collision" (the motion's first contact, drawn marked: first_contact_of_motion),
    // "boundary" (the head reaching the turning space), "end" (the end of the valid motion).
    // Empty: "collision" on the plain spiral, "100m" on the turnaround path.
    std::string to;
    double speedup = 10.0;        // simulated seconds per second of film
    std::optional<double> hold;   // s the last moment stays; unset: 1 at a collision, else 0
};

// How the caller names the request's two ends in its messages (the tool: its flags, --from, --to).
struct ClipWords {
    std::string from = "from", to = "to";
};

// The clip, the benches touching at its end (to = collision) and the captions of its events.
struct ClipPlan {
    Clip clip;
    std::optional<CollisionMark> end_mark;
    std::vector<FilmEvent> events;
};

// Throws InputError (naming the ends by `words`) for a moment that is neither a time nor
// travel nor an event, an event the motion does not have (no contact in the motion's window,
// a head already inside the turning space, a motion that never ends), a moment past the valid
// motion, or an empty range.
ClipPlan plan_clip(const Simulation& sim, const ClipRequest& request, const ClipWords& words = {});

}  // namespace dragon
