// The search for the end of the valid motion (dragon/valid_motion.hpp) as a walk that can be
// resumed: it steps along the head's arc position from where it began, one way, and each call
// takes it further. Its steps are never cut short at the place a call asked about, so the walk
// takes the same steps, and finds the same jam to the last bit, however far each call asked it
// to go: a Simulation whose frames are asked for by threads in any order finds one end of its
// motion, and one that is asked for a late moment first finds the same one.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "dragon/chain.hpp"
#include "dragon/valid_motion.hpp"

namespace dragon::jam {

// A jam as a walk finds it, in arc position: the motion is continuous at `valid`, not at `past`.
struct Found {
    double valid = 0.0, past = 0.0;
    int link = 0;                           // 0..N-1: the link whose rear handle would jump
    JamKind kind = JamKind::root_vanishes;  // as the walk's direction sees it
    Vec2 point = Vec2::Zero();
    double proved = 0.0;  // arc position: the motion is proved continuous from the walk's start to here
    int proved_steps = 0, unproved_steps = 0;  // the walk's, up to the jam
};

// How a walk chooses and proves its steps (the defaults but in tests).
struct WalkOptions {
    bool prove = true;  // prove each step (motion_proof.hpp); false: the rate check at its end alone
    // And the links that turn too far for the turning proof, by their health (JamSearchOptions::prove)
    bool prove_health = false;
    bool prove_backing = false;  // and past rear handles that may back up (with prove_health)
    // Multiplies every step the rates allow (> 1: steps longer than the rates warrant, to show
    // what the proof catches that the end check does not).
    double step_scale = 1.0;
    bool check_ends = true;  // check each step's rate bounds at its end (false: tests only)
    // Every step accepted, in arc position (from, to), and whether it was proved: for tests.
    struct Step {
        double from, to;
        bool proved;
    };
    std::vector<Step>* log = nullptr;
};

class Walk {
public:
    // From the chain the nearest-root rule gives at arc position `from`, in direction `dir` (+1
    // ahead, -1 back), never past `end` (the path's end that way, or an infinity).
    Walk(const Path& path, const BenchSpec& spec, double from, double dir, double end, const WalkOptions& options = {});
    ~Walk();
    Walk(const Walk&) = delete;
    Walk& operator=(const Walk&) = delete;

    // Walks on until the motion is known continuous at `target` or beyond, a jam is found, the
    // walk reaches `end`, or the motion is certified continuous for ever.
    void advance(double target);
    // The motion is continuous from `from` to here (infinite once certified for ever).
    double known() const;
    // And proved so, step by step (section 4.1), from `from` to here.
    double proved() const;
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
