// A proof that the valid motion holds over a whole step of head travel, from the chain at the
// step's two ends alone (docs/methods.md, section 4.1): no rear handle's root vanishes and no
// nearer root appears anywhere inside it. The walk of valid_motion.cpp chooses its steps by the
// rates of its links' margins; this proves them.
//
// Link by link from the head, each front handle known to stay, over the step, on the arc between
// its places at the step's ends (the head's is its own travel):
//  - turning (gentle_link.hpp): the path from the rear handle's place at the start to the front
//    handle's at the end turns by less than pi/2. For every front place q on its arc the
//    distance from P(q) then grows strictly going back over that hull, is at least the link's
//    length d at the rear's start place and at most d at its end place: the nearest root behind
//    q is unique and simple, and lies between the rear's two places, which carries the induction
//    to the next link;
//  - calm (link_watch.hpp): the front's place at the end is at or behind the stretch where the
//    path is calm for the link; then at every moment of the step the whole link is on calm
//    path, spans less than pi/2 of turning (Schur), and its rear moves forward.
// With `health` (the links that turn further), each half of the step is proved from its end
// alone: the front handle stays within a known arc of its place there, the health
// h(q, t) = max(d - R, (d/2) dR/dsigma) moves by at most that arc's reach as the front moves
// (Lipschitz constant 1 where R >= d/2), and a lower bound on the health over a fixed range of
// the path behind the front at that end (dense samples less their Lipschitz error) above that
// reach proves the rear's root unique and simple for every front place in the arc. The rear is
// then known only to lie in a range around its place (no longer between its two places), and the
// links behind are proved half by half too: by the turning argument over ranges, or by the
// health again.
#pragma once

#include <vector>

#include "link_watch.hpp"
#include "dragon/chain.hpp"
#include "dragon/path.hpp"
#include "dragon/scenario.hpp"

namespace dragon::jam {

enum class MotionVerdict {
    proved,     // no jam anywhere in the step
    backwards,  // handle `link` ends behind where it began: no proof by turning past it
    turns,      // link `link` passes no test: a shorter step may pass
    backs,      // handle `link` may back up over the step (and `backing` was not asked for)
};

struct MotionStepProof {
    MotionVerdict verdict = MotionVerdict::proved;
    int link = -1;  // the first link not proved, 0..N-1 (its rear handle is link + 1), or the handle that went back
    bool health = false;  // some link was proved by its health (the step's halves)
};

// Scratch kept between proofs.
struct MotionProofWork {
    // Where each handle may be over each half of the step: between two places (half 0: the
    // lesser head arcs, around the handle's place at the start), each with its arc position.
    struct End {
        Located at;
        double arc = 0.0;  // m
    };
    struct Span {
        End lo[2], hi[2];
    };
    std::vector<Span> spans;
    std::vector<double> arcs[2];  // each handle's arc position at the step's two ends (NaN: not yet)
};

// Proves (or fails to prove) that the chain is continuous at every head arc position between
// lo's and hi's (lo.head_arc <= hi.head_arc, both chains of `spec` on `path` solved by the
// nearest-root rule). head, body: where the path is calm for the head's link and the others.
// health: links that turn too far for the turning argument are tried by their health, as long as
// their rear handles move forward (the links behind then go back to the turning argument);
// backing: also past a rear handle that may back up (every link behind is then proved half by
// half over ranges: several times the cost of a step).
MotionStepProof prove_motion_step(const Path& path, const BenchSpec& spec, const Frame& lo, const Frame& hi,
                                  const Calm& head, const Calm& body, bool health, bool backing,
                                  MotionProofWork& work);

}  // namespace dragon::jam
