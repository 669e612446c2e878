// The search for the end of the valid motion (dragon/valid_motion.hpp) as a walk that can be
// resumed: it steps along the head's arc position from where it began, one way, and each call
// takes it further. Its steps are never cut short at the place a call asked about, so the walk
// takes the same steps, and finds the same jam to the last bit, however far each call asked it
// to go: a Simulation whose frames are asked for by threads in any order finds one end of its
// motion, and one that is asked for a late moment first finds the same one.
#pragma once

#include <memory>
#include <optional>

#include "dragon/chain.hpp"
#include "dragon/valid_motion.hpp"

namespace dragon::jam {

// A jam as a walk finds it, in arc position: the motion is continuous at `valid`, not at `past`.
struct Found {
    double valid = 0.0, past = 0.0;
    int link = 0;                           // 0..N-1: the link whose rear handle would jump
    JamKind kind = JamKind::root_vanishes;  // as the walk's direction sees it
    Vec2 point = Vec2::Zero();
};

class Walk {
public:
    // From the chain the nearest-root rule gives at arc position `from`, in direction `dir` (+1
    // ahead, -1 back), never past `end` (the path's end that way, or an infinity).
    Walk(const Path& path, const BenchSpec& spec, double from, double dir, double end);
    ~Walk();
    Walk(const Walk&) = delete;
    Walk& operator=(const Walk&) = delete;

    // Walks on until the motion is known continuous at `target` or beyond, a jam is found, the
    // walk reaches `end`, or the motion is certified continuous for ever.
    void advance(double target);
    // The motion is continuous from `from` to here (infinite once certified for ever).
    double known() const;
    // Nothing is left to find: a jam was found, `end` reached, or the motion certified for ever.
    bool finished() const;
    const std::optional<Found>& found() const;
    const JamSearchStats& stats() const;

private:
    struct State;
    std::unique_ptr<State> state_;
};

// A walk's jam as a Jam on the timeline head arc = start_arc + head_speed * t, described as time
// runs forward (a walk going back sees each event reversed).
Jam to_jam(const Found& f, double dir, double start_arc, double head_speed);

}  // namespace dragon::jam
