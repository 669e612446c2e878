// The search for the end of the valid motion (the method is described in dragon/valid_motion.hpp).
#include "dragon/valid_motion.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "chain_front.hpp"
#include "jam_walk.hpp"
#include "link_watch.hpp"
#include "motion_proof.hpp"
#include "dragon/chain.hpp"
#include "dragon/constants.hpp"
#include "dragon/errors.hpp"

#include <fmt/format.h>

namespace dragon {

const char* to_string(JamKind k) {
    switch (k) {
        case JamKind::root_vanishes: return "root_vanishes";
        case JamKind::nearer_root: return "nearer_root";
    }
    return "?";
}

namespace {

using jam::kSafety;
using jam::LinkCheck;

constexpr double kMaxTravel = jam::kMaxStep;
// Below this fraction of half a link's length, a link's health is close enough to zero to try
// bracketing the tangency that would end the motion.
constexpr double kProbeHealth = 0.05;
// Halvings a step gets for a link proved by its health before it is accepted on the rate check.
constexpr int kHealthHalvings = 4;
// A search needing more evaluations than this has a broken bound: fail loudly, never hang.
constexpr int kMaxEvaluations = 100000;
// Bracketing a watched tangency: its excess is looked at this many predicted distances ahead
// (a prediction from the excess's rate now, which grows as the jam nears), then narrowed by at
// most kFalsiIterations steps of regula falsi (each at least halves the bracket every other step).
constexpr double kProbeReach[] = {1.5, 3.0, 6.0};
constexpr int kFalsiIterations = 200;
// A step whose bound broke is taken again this much shorter.
constexpr double kRetryShrink = 0.25;
// Roundings of the head's arc position that its resolution allows at least (resolution()).
constexpr double kArcRoundings = 4.0;

double resolution(double s, double tolerance);

struct Evaluation {
    double s = 0.0;  // the head's arc position, m
    Frame frame;
    std::vector<LinkCheck> links;
    double step = INFINITY;  // head travel no link's margin can run out in, m
    int critical = 0;        // the link setting it
};

// Where a jam lies: `valid` is continuous, `past` is not, |past - valid| <= the tolerance.
struct Bracket {
    double valid = 0.0, past = 0.0;  // the head's arc positions, m
    int link = 0;
    JamKind kind = JamKind::root_vanishes;
    Vec2 point = Vec2::Zero();
};

class JamSearch {
public:
    JamSearch(const Path& path, const BenchSpec& spec, double dir, double arc_tolerance, JamSearchStats& stats)
        : path_(path), spec_(spec), dir_(dir), arc_tol_(arc_tolerance), stats_(stats),
          calm_head_(jam::calm_for(path, spec.link_length(1))),
          calm_body_(spec.bench_count > 1 ? jam::calm_for(path, spec.link_length(2)) : calm_head_) {}

    void evaluate(double s, Evaluation& e) {
        if (++stats_.evaluations > kMaxEvaluations)
            throw SolverError("jam search: no end within its allowance of evaluations (a broken bound)");
        e.s = s;
        solve_chain(path_, spec_, s, 1.0, e.frame);
        const size_t links = e.frame.benches.size();
        e.links.resize(links);
        e.step = INFINITY;
        e.critical = 0;
        for (size_t k = 0; k < links; ++k) {
            e.links[k] = jam::check_link(path_, e.frame.handles[k], e.frame.handles[k + 1],
                                         spec_.link_after(static_cast<int>(k)), k == 0 ? calm_head_ : calm_body_, dir_);
            if (e.links[k].step < e.step) e.step = e.links[k].step, e.critical = static_cast<int>(k);
        }
    }

    // Did the step from `a` to `b` keep every bound it relied on? Each margin may have fallen by
    // at most margin * travel / step; each handle may have moved at most kSafety times its
    // larger speed times the travel (a handle that jumped to another root moves far more).
    // Returns -1 if so, else the first link whose bound broke.
    int step_held(const Evaluation& a, const Evaluation& b) const {
        const double travel = std::abs(b.s - a.s);
        for (size_t k = 0; k < a.links.size(); ++k) {
            const LinkCheck& x = a.links[k];
            const LinkCheck& y = b.links[k];
            const double floor = x.margin * (1.0 - travel / x.step) * (1.0 - tol::promise_relative) - tol::promise_margin;
            if (x.calm) {
                // Still on calm path, or at least within a quarter turn (a link that left the
                // calm stretch early has its turning checked instead).
                if (!y.calm && jam::kQuarterTurn - y.turn <= 0.0) return static_cast<int>(k);
            } else if (x.gentle) {
                // Its turning must have stayed within the allowance, whatever it is now.
                if (jam::kQuarterTurn - y.turn < floor) return static_cast<int>(k);
            } else if (!y.gentle && y.margin < floor) {
                return static_cast<int>(k);  // (one that turned gentle is certified outright)
            }
        }
        for (size_t i = 0; i < a.frame.handles.size(); ++i) {
            const Handle& p = a.frame.handles[i];
            const Handle& q = b.frame.handles[i];
            const double reach = kSafety * std::max(std::abs(p.speed), std::abs(q.speed)) * travel + tol::promise_move;
            if (!(distance(p.pos, q.pos) <= reach)) return static_cast<int>(std::max<size_t>(i, 1) - 1);
        }
        return -1;
    }

    // The watched tangency of link k, bracketed and narrowed to the tolerance; nullopt when its
    // excess does not cross zero within a few predicted distances.
    std::optional<Bracket> bracket(const Evaluation& e, int k) {
        const double chord = spec_.link_after(k);
        const double window = 0.5 * chord;
        const Handle& front = e.frame.handles[static_cast<size_t>(k)];
        const auto tangency0 = jam::watch_tangency(path_, front.pos, chord, e.links[static_cast<size_t>(k)].watch_arc, window);
        if (!tangency0) return std::nullopt;
        if (tangency0->excess == 0.0) return Bracket{e.s, e.s, k, JamKind::root_vanishes, tangency0->point};
        // The tangency's excess changes with the head's travel at -dir . (velocity of handle k).
        const double slope = -dot(tangency0->dir, front.tangent) * front.speed * dir_;
        if (!(slope * tangency0->excess < 0.0)) return std::nullopt;  // not heading for zero
        const double predicted = -tangency0->excess / slope;
        // The excess is positive while a root-to-be-lost still has its hump beyond the chord.
        const JamKind kind = tangency0->excess > 0.0 ? JamKind::root_vanishes : JamKind::nearer_root;
        double seed = tangency0->arc;
        auto excess_at = [&](double s) -> std::optional<double> {
            solve_chain_front(path_, spec_, s, 1.0, k + 1, scratch_);
            ++stats_.evaluations;
            const auto tangency = jam::watch_tangency(path_, scratch_.handles[static_cast<size_t>(k)].pos, chord, seed, window);
            if (!tangency) return std::nullopt;
            seed = tangency->arc;
            last_point_ = tangency->point;
            return tangency->excess;
        };
        double valid = e.s, g_valid = tangency0->excess, past = NAN, g_past = NAN;
        for (double reach : kProbeReach) {
            const double travel = std::min(reach * predicted, kMaxTravel);
            const double s = e.s + dir_ * travel;
            const auto g = excess_at(s);
            if (!g) return std::nullopt;
            if ((*g > 0.0) != (g_valid > 0.0) || *g == 0.0) {
                past = s, g_past = *g;
                break;
            }
            if (travel == kMaxTravel) break;
        }
        if (std::isnan(past)) return std::nullopt;
        // Regula falsi (Illinois) on the head's arc position.
        int side = 0;
        for (int it = 0; it < kFalsiIterations && std::abs(past - valid) > resolution(valid, arc_tol_); ++it) {
            double s = valid + g_valid * (past - valid) / (g_valid - g_past);
            if (!((s - valid) * dir_ > 0.0 && (past - s) * dir_ > 0.0)) s = 0.5 * (valid + past);
            if (s == valid || s == past) break;
            const auto g = excess_at(s);
            if (!g) return std::nullopt;
            if ((*g > 0.0) == (g_valid > 0.0) && *g != 0.0) {
                valid = s, g_valid = *g;
                if (side == +1) g_past *= 0.5;
                side = +1;
            } else {
                past = s, g_past = *g;
                if (side == -1) g_valid *= 0.5;
                side = -1;
            }
        }
        return Bracket{valid, past, k, kind, last_point_};
    }

    const jam::Calm& calm_head() const { return calm_head_; }
    const jam::Calm& calm_body() const { return calm_body_; }

private:
    const Path& path_;
    const BenchSpec& spec_;
    double dir_;
    double arc_tol_;  // m of the head's arc position: where jams are located to
    JamSearchStats& stats_;
    jam::Calm calm_head_, calm_body_;  // for the head's link and the others
    Frame scratch_;
    Vec2 last_point_ = Vec2::Zero();
};

// The tolerance on the head's arc position at s: the one asked for, or a few roundings of s
// itself where those are larger.
double resolution(double s, double tolerance) {
    const double a = std::abs(s);
    return std::max(tolerance, kArcRoundings * (std::nextafter(a, INFINITY) - a));
}

double longest_link(const BenchSpec& spec) {
    double d = spec.link_length(1);
    if (spec.bench_count > 1) d = std::max(d, spec.link_length(2));
    return d;
}

JamKind reversed(JamKind k) { return k == JamKind::root_vanishes ? JamKind::nearer_root : JamKind::root_vanishes; }

}  // namespace

namespace jam {

struct Walk::State {
    State(const Path& path, const BenchSpec& spec, double dir, const WalkOptions& options)
        : path(path), spec(spec), dir(dir), options(options), search(path, spec, dir, tol::travel, stats) {}
    const Path& path;
    const BenchSpec& spec;
    double dir;
    WalkOptions options;
    double end = 0.0;
    double calm_head = 0.0;  // the walk going back ends here: the motion is continuous behind it for ever
    JamSearchStats stats;
    JamSearch search;
    Evaluation cur, next;
    std::optional<Bracket> candidate;
    double probed_at = INFINITY;  // m: the margin at the last probe that found nothing
    double retry_cap = INFINITY;  // m of head travel: after a broken bound, retry shorter from cur
    double proof_cap = INFINITY;  // the longest step the proof is expected to prove (halved when it fails)
    double proved = 0.0;          // the motion is proved continuous from the walk's start to here
    int health_halvings = 0;      // halvings of this step for its links' health (at most kHealthHalvings)
    MotionProofWork proof_work;
    bool proving = true;          // every step so far proved (`proved` follows the walk)
    bool done = false, forever = false;
    std::optional<Found> found;

    void finish(const Bracket& b) {
        found = Found{b.valid, b.past, b.link, b.kind, b.point, proved, stats.proved_steps, stats.unproved_steps};
        done = true;
    }
    // Proves the step from cur to next (section 4.1). Returns false when it was not proved but a
    // shorter one may be: the step is to be taken again shorter.
    bool prove_step(double travel, double here_tol);
    // One step of the walk (or one probe for a bracket, or one retreat).
    void step();
};

Walk::Walk(const Path& path, const BenchSpec& spec, double from, double dir, double end, const WalkOptions& options)
    : state_(std::make_unique<State>(path, spec, dir, options)) {
    State& w = *state_;
    w.end = end;
    // Head at or behind `calm_head`: every link lies where the curvature is small for the
    // longest link, and moving back it stays there (all handles move with the head then).
    w.calm_head = path.curvature_bounded_before(kCalmBend / longest_link(spec));
    double s = from;
    // A path calm everywhere (a turning space far wider than the longest link) bends no link
    // enough to lose a root, in either direction.
    if (w.calm_head == INFINITY) {
        w.done = w.forever = true;
        return;
    }
    if (dir > 0.0 && s < w.calm_head) s = std::min(w.calm_head, end);
    if ((dir < 0.0 && s <= w.calm_head)) {
        w.done = w.forever = true;
        return;
    }
    if (!std::isfinite(s))
        throw SolverError(fmt::format("the valid-motion walk cannot start at head travel {} m", s));
    // Up to s the path is calm for every link (or s is where the walk starts).
    w.proved = s;
    w.search.evaluate(s, w.cur);
    if (s == end) w.done = true;
}

Walk::~Walk() = default;

void Walk::State::step() {
    // Every link on calm path and moving away from where it ends: with all links calm every
    // handle moves with the head, so they stay calm for ever.
    if (cur.step == INFINITY || (dir < 0.0 && cur.s <= calm_head)) {
        done = forever = true;
        return;
    }
    const LinkCheck& crit = cur.links[static_cast<size_t>(cur.critical)];
    if (candidate && (candidate->valid - cur.s) * dir <= cur.step) return finish(*candidate);
    const double here_tol = resolution(cur.s, tol::travel);
    if (!(cur.step > here_tol)) {
        // The margins ran out here without a bracket: the jam is at this moment, to the tolerance.
        return finish({cur.s, cur.s + dir * here_tol, cur.critical,
                       crit.at_root ? JamKind::root_vanishes : JamKind::nearer_root,
                       path.at_arc(crit.gentle ? cur.s : crit.watch_arc).pos});
    }
    const double probe_below = kProbeHealth * 0.5 * spec.link_after(cur.critical);
    if (!candidate && !crit.gentle && crit.margin < probe_below && crit.margin < 0.5 * probed_at) {
        candidate = search.bracket(cur, cur.critical);
        if (!candidate) probed_at = crit.margin;
        return;
    }
    // Steps are cut short only at the walk's end, never at a place a caller asked about.
    const double travel = std::min({cur.step * options.step_scale, kMaxTravel, retry_cap, proof_cap, (end - cur.s) * dir});
    const double to = travel == (end - cur.s) * dir ? end : cur.s + dir * travel;
    search.evaluate(to, next);
    if (const int broken = options.check_ends ? search.step_held(cur, next) : -1; broken >= 0) {
        if (travel > here_tol) {
            retry_cap = kRetryShrink * travel;
            ++stats.retreats;
            return;
        }
        // Within the tolerance of here, link `broken` lost its root.
        const LinkCheck& l = cur.links[static_cast<size_t>(broken)];
        return finish({cur.s, to, broken, l.gentle || l.at_root ? JamKind::root_vanishes : JamKind::nearer_root,
                       cur.frame.handles[static_cast<size_t>(broken) + 1].pos});
    }
    if (!prove_step(travel, here_tol)) return;
    std::swap(cur, next);
    retry_cap = INFINITY;
    if (candidate && (cur.s - candidate->valid) * dir > 0.0) candidate.reset();  // it was not in the way
    if (cur.s == end) done = true;
}

bool Walk::State::prove_step(double travel, double here_tol) {
    const Evaluation& lo = dir > 0.0 ? cur : next;
    const Evaluation& hi = dir > 0.0 ? next : cur;
    // Past the first step left unproved the proof could not extend `proved` any more: the
    // rest of the walk rests on the rate check, and costs no proof.
    const bool attempt = options.prove && proving;
    const MotionStepProof p = attempt ? prove_motion_step(path, spec, lo.frame, hi.frame, search.calm_head(),
                                                                search.calm_body(), options.prove_health,
                                                                options.prove_backing, proof_work)
                                            : MotionStepProof{MotionVerdict::turns, 0, false};
    if (p.verdict != MotionVerdict::proved && attempt && travel > here_tol) {
        // A shorter step may prove what this one did not: a link that turns gently at the step's
        // start (its hull then turns little more over a short step), or a handle that moves
        // forward there. Other links cannot be proved by turning at any length; their health
        // needs the front's reach over each half below the health, which a shorter step may give
        // (a few halvings: near a jam the health falls as fast as the steps the rates allow).
        const size_t k = static_cast<size_t>(p.link);
        const bool gentle_start = p.verdict == MotionVerdict::turns && (cur.links[k].calm || cur.links[k].gentle);
        // (speeds are per unit of head travel ahead: a handle ends ahead of where it began, in arc
        // order, when its speed is positive, whichever way the walk goes)
        const bool forward_start = cur.frame.handles[k].speed > 0.0;
        const bool health_may = options.prove_health && health_halvings < kHealthHalvings;
        const bool shorter_may = p.verdict == MotionVerdict::turns       ? gentle_start || health_may
                                 : p.verdict == MotionVerdict::backwards ? forward_start
                                                                         : forward_start && health_may;
        if (shorter_may) {
            if (!gentle_start) ++health_halvings;
            proof_cap = 0.5 * travel;
            ++stats.subdivisions;
            return false;
        }
    }
    health_halvings = 0;
    const bool proved_here = p.verdict == MotionVerdict::proved;
    if (proved_here) {
        ++stats.proved_steps;
        if (proving) proved = next.s;
    } else {
        ++stats.unproved_steps;
        stats.unproved_travel += travel;
        // The rest rests on the rate check: its steps as long as the rates allow.
        if (proving) proof_cap = INFINITY;
        proving = false;
    }
    // As long as the last step the proof allowed: try a little longer next.
    if (travel >= proof_cap) proof_cap *= 1.5;
    if (options.log) options.log->push_back({std::min(cur.s, next.s), std::max(cur.s, next.s), proved_here});
    return true;
}

void Walk::advance(double target) {
    State& w = *state_;
    while (!w.done && (target - w.cur.s) * w.dir > 0.0) w.step();
}

double Walk::proved() const {
    const State& w = *state_;
    if (w.forever && w.proving) return w.dir * INFINITY;
    return w.proved;
}

double Walk::known() const {
    const State& w = *state_;
    if (w.forever) return w.dir * INFINITY;
    if (w.found) return w.found->valid;
    return w.cur.s;
}

bool Walk::finished() const { return state_->done; }
const std::optional<Found>& Walk::found() const { return state_->found; }
const JamSearchStats& Walk::stats() const { return state_->stats; }

Jam to_jam(const Found& f, double dir, double start_arc, double head_speed) {
    Jam j;
    j.head_arc = f.valid;
    j.travel = f.valid - start_arc;
    j.time = j.travel / head_speed;
    j.handle = f.link + 1;
    j.kind = dir > 0.0 ? f.kind : reversed(f.kind);
    j.ahead = dir > 0.0;
    j.point = f.point;
    // How far past `time` the motion may still go: the bracket, and the rounding of t itself.
    j.travel_tolerance = std::abs(f.past - f.valid);
    j.proved_travel = f.proved - start_arc;
    j.proved_time = j.proved_travel / head_speed;
    j.proved_steps = f.proved_steps;
    j.unproved_steps = f.unproved_steps;
    const double rounding = std::abs(std::nextafter(j.time, dir * INFINITY) - j.time);
    j.tolerance = std::max(j.travel_tolerance / head_speed, rounding);
    return j;
}

}  // namespace jam

std::optional<Jam> find_jam(const Path& path, const BenchSpec& spec, double start_arc, double head_speed,
                            double t_from, double t_to, JamSearchStats* stats_out, const JamSearchOptions& options) {
    const double s_from = start_arc + head_speed * t_from;
    const double s_to = start_arc + head_speed * t_to;
    if (!(s_to != s_from)) return std::nullopt;
    const double dir = s_to > s_from ? 1.0 : -1.0;
    jam::WalkOptions walk_options;
    walk_options.prove_health = walk_options.prove_backing = options.prove;
    jam::Walk walk(path, spec, s_from, dir, s_to, walk_options);
    walk.advance(s_to);
    if (stats_out) *stats_out = walk.stats();
    if (!walk.found()) return std::nullopt;
    return jam::to_jam(*walk.found(), dir, start_arc, head_speed);
}

}  // namespace dragon
