// Where the dragon can follow its path.
//
// Each handle is the nearest chord root behind the one in front. That rule gives a motion only
// while every handle moves continuously, and it can stop doing so in two ways:
//  - root_vanishes: the rear handle's root merges with the next root behind it and disappears.
//    Just before, the path at the rear handle turns square to its link (the circle of the
//    link's length about the front handle touches the path there), so the rear handle's speed
//    has no bound.
//  - nearer_root: the path between the two handles swings back out to the link's length: a
//    double root is born between them, nearer than the rear handle's, which would jump to it.
// Past the first such moment the tables, pictures and answers of the nearest-root rule are
// those of a dragon whose benches teleport, so no computation may use them. Near the spiral's
// centre and on S-curves with an arc too tight for a bench that moment comes.
#pragma once

#include <optional>

#include "dragon/geometry.hpp"
#include "dragon/path.hpp"
#include "dragon/scenario.hpp"

namespace dragon {

// How the valid motion ends (see the file's comment): the followed root vanishes, or a nearer
// one is born.
enum class JamKind { root_vanishes, nearer_root };
// "root_vanishes" or "nearer_root".
const char* to_string(JamKind k);

// The end of the valid motion. One event is described one way whichever side it was found
// from: `kind` is what happens as time runs forward (a jam behind t = 0, found by a search
// going back, is the reverse of what that search saw: a root born there going back is the
// followed root vanishing going forward, and the other way round), and `ahead` says on which
// side of it the motion is valid.
struct Jam {
    double time = 0.0;       // s: the last moment known to be continuous, within `tolerance` of the end
    double travel = 0.0;     // m: the head's travel from t = 0 then (time * head speed; the geometry's own clock)
    double head_arc = 0.0;   // m: the head's arc position then
    int handle = 0;          // 1..N: the handle that would have to jump; its link's front is handle - 1
    JamKind kind = JamKind::root_vanishes;  // as time runs forward
    // The motion is valid until the jam (it lies ahead of where the search began, t = 0 for a
    // Simulation); false: valid from it on.
    bool ahead = true;
    Vec2 point = Vec2::Zero();  // where the circle of the link's length about handle - 1 touches the path
    double tolerance = 0.0;  // s: the motion stops within this much of `time`, on the far side of it
    double travel_tolerance = 0.0;  // m: the same as head travel
    // What the search proved (docs/methods.md, section 4.1). The motion is proved continuous
    // from t = 0 to `proved_travel` (m of head travel; every step up to there proved, or the
    // path certified calm there); the jam lies between it and `travel` + `travel_tolerance` (on
    // the other side of t = 0 for a jam behind): its enclosure.
    double proved_travel = 0.0;
    double proved_time = 0.0;  // s: the same as time
    int proved_steps = 0;    // steps of the search proved jam-free from the chain at their ends
    int unproved_steps = 0;  // steps accepted on their rates checked at their ends alone
    // "turning" (every step proved), "rate" (none) or "turning+rate" (some on the rate check alone).
    const char* method() const {
        return unproved_steps == 0 ? "turning" : proved_steps == 0 ? "rate" : "turning+rate";
    }
};

// Does the valid motion's own handle race without bound as the jam nears? Yes where the root it
// follows vanishes there: going forward at a jam ahead (root_vanishes), going back at a jam
// behind (seen forward, a nearer root is born: the followed root's twin, on the valid side).
inline bool speed_unbounded_at(const Jam& j) {
    return j.ahead ? j.kind == JamKind::root_vanishes : j.kind == JamKind::nearer_root;
}

// How a jam search went (for tests and benchmarks).
struct JamSearchStats {
    int evaluations = 0;  // chains solved and checked
    int retreats = 0;     // steps taken back because a bound the step relied on was broken
    int proved_steps = 0;    // steps proved jam-free from the chain at their two ends (section 4.1)
    int unproved_steps = 0;  // steps accepted on their rates checked at their ends alone
    int subdivisions = 0;    // steps the proof failed, taken again shorter
    double unproved_travel = 0.0;  // m of head travel the unproved steps cover
};

// How a jam search proves its steps (docs/methods.md, section 4.1). Every step where each link
// turns gently (its path turning by less than pi/2 over the step) is proved by default; the
// others rest on their rates checked at their ends, unless `prove`.
struct JamSearchOptions {
    // Prove those too, by each link's health over each half of the step (and every link behind a
    // handle that may back up over ranges of its places): the motion is then proved to within
    // about 1e-8 m of the jam. Opt-in: on the contest's spiral it costs about 45 times the search.
    bool prove = false;
};

// The first jam met as the head's arc position runs from s_from towards s_to (either way), or
// nullopt when the motion stays continuous all along. The chain there is the one the
// nearest-root rule gives at s_from. s_to may be infinite: the search then ends where the motion
// is certified continuous for ever (the path ahead, or behind, curves too gently for any link to
// lose its root). Times are on the timeline head arc = start_arc + head_speed * t; the search
// itself runs in arc position, so where it finds a jam does not depend on the head's speed, and
// a jam is located to tol::travel metres of head travel.
//
// Method. A link whose path turns by less than pi/2 between its handles keeps a simple, unique
// root; its step lasts until that turning could reach pi/2 at its current rate of change. Other
// links get the health h = min over the path between the handles of
//     max(d - R, (d/2) dR/dsigma),   R: distance from the front handle, sigma: arc back from it,
// which is positive exactly while no jam has happened, changes at a fixed place at most at the
// front handle's speed, and at the moving rear end as c^2 near a vanishing root (c = dR/dsigma
// there). Steps last until the health could reach zero at kSafety times its current rate, and
// the next evaluation checks every bound the step relied on (a broken one sends the search back
// with a shorter step). Near a jam the local maximum of R nearest the watched tangency crosses d:
// that smooth function of the head's position is bracketed and refined by regula falsi, and the
// steps close in on it until none could miss an earlier jam. Stretches where the path's
// curvature k satisfies k d <= 1.3 are certified at once: by Schur's comparison theorem the link
// then spans at most 2 asin(k d / 2) < pi/2 of turning.
std::optional<Jam> find_jam(const Path& path, const BenchSpec& spec, double start_arc, double head_speed,
                            double t_from, double t_to, JamSearchStats* stats = nullptr,
                            const JamSearchOptions& options = {});

}  // namespace dragon
