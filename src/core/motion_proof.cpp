// Proof that a step of the valid-motion walk holds no jam (motion_proof.hpp).
#include "motion_proof.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "gentle_link.hpp"
#include "path_part.hpp"
#include "dragon/portable_math.hpp"

namespace dragon::jam {

namespace {

// m: every inequality the health and the ranges must pass holds with this to spare. It covers the
// chain solve's error in each handle (~1e-14 m, section 2), the rounding of distances and arc
// positions of a few hundred metres (~1e-13 m) and of the health's few operations: 1e-9 m is
// thousands of times all of them. It sets how close to a jam the health can prove the motion.
constexpr double kHealthSlack = 1e-9;
// The health's first samples: one per this much of each piece's parameter (rad: about as much
// turning on the spirals, exactly on the arcs), then intervals whose bound falls short are halved.
constexpr double kSampleTurn = 0.05;
constexpr int kMaxSamplesPerPiece = 400;
// Samples one half of one link may take: a health too close to its need for this many is left
// unproved (a shorter step needs less).
constexpr int kSampleBudget = 3000;
// A rear handle's range is first guessed from its front's as the speed ratio times (1 + this)
// (plus this): along 223 links that compounds to about 1.6.
constexpr double kFirstWidening = 2e-3;
// Guesses at a range's ends: the far end of the health's range and the rear's far side (each try
// doubles the last), a rear handle's range (each try widens it four times as much).
constexpr int kTries = 8;

using End = MotionProofWork::End;

struct Range {
    End lo, hi;
};

End end_at(const Path& path, const Located& p) { return {p, path.arc(p.place)}; }

// The place about `shift` of arc from `from` (at arc position `arc`): one step of Newton on the
// piece's parameter (the arc's rate measured there), or Path::at_arc off the piece. Only a guess:
// the place's own arc is computed, and the proofs check what they need of it.
End shifted(const Path& path, const End& from, double shift) {
    const Place& p = from.at.place;
    const auto [begin, end] = path.piece_span(p.piece);
    const double sign = end > begin ? 1.0 : -1.0;
    constexpr double kProbe = 1e-6;  // of the parameter (rad)
    const double rate = (path.arc({p.piece, p.u + sign * kProbe}) - from.arc) / kProbe;
    const double u = p.u + sign * shift / rate;
    const bool inside = std::isfinite(u) && rate > 0.0 && (u - begin) * (u - end) <= 0.0;
    if (!inside) {
        const double s = std::clamp(from.arc + shift, path.s_min(), path.s_max());
        return end_at(path, path.at_arc(s));
    }
    return end_at(path, path.at({p.piece, u}));
}

// What the health proved of a rear handle over a half: its range, and how far from its place at
// the half's end it may be (m), with the front's reach.
struct HealthHalf {
    Range rear;
    double rear_reach = 0.0, front_reach = 0.0;
};

Located located(const Handle& h) { return {h.place, h.pos, h.tangent, {}}; }

// The health of the point p for a front handle at q: max(d - R, (d/2) dR/dsigma).
double health_at(const Located& p, const Vec2& q, double d) {
    const Vec2 w = q - p.pos;
    const double r = norm(w);
    if (!(r > 0.0)) return d;
    return std::max(d - r, 0.5 * d * dot(w, p.tangent) / r);
}

// The largest |curvature| between places a (behind) and b (0 when b is behind a).
double largest_curvature(const Path& path, const Place& a, const Place& b) {
    const auto [lo, hi] = curvature_range(path, a, b);
    return lo > hi ? 0.0 : std::max(std::abs(lo), std::abs(hi));
}

struct Sample {
    double u, arc, h;
};

// Whether the health of a front handle at q exceeds `need` all along the path between places a
// (behind) and b. Between two samples t_a, t_b an arc length D apart it is at least
// min((h_a + h_b) / 2 - L D / 2, d / 2 - D): where R >= d / 2 all along, h is L-Lipschitz in arc
// length, L = 1 + (d/2) max|curvature| (|dR/dt| <= 1, (d/2) |d(dR/dsigma)/dt| <= (d/2) (1/R + |k|));
// where R < d / 2 somewhere, R < d / 2 + D everywhere on it and h >= d - R. Intervals whose bound
// falls short are halved, within `budget` samples.
bool health_above(const Path& path, const Vec2& q, double d, const Place& a, const Place& b, double need, int budget) {
    const double lipschitz = 1.0 + 0.5 * d * largest_curvature(path, a, b);
    const auto sample = [&](int piece, double u) {
        const Place p{piece, u};
        return Sample{u, path.arc(p), health_at(path.at(p), q, d)};
    };
    std::vector<std::pair<Sample, Sample>> stack;
    for (int piece = a.piece; piece <= b.piece; ++piece) {
        const auto [u0, u1] = part_of(path, piece, a, b);
        const int n = std::clamp(static_cast<int>(std::ceil(std::abs(u1 - u0) / kSampleTurn)), 2, kMaxSamplesPerPiece);
        Sample prev = sample(piece, u0);
        for (int j = 1; j <= n; ++j) {
            const Sample next = sample(piece, j == n ? u1 : u0 + (u1 - u0) * j / n);
            stack.push_back({prev, next});
            while (!stack.empty()) {
                const auto [x, y] = stack.back();
                stack.pop_back();
                if (!(x.h > need) || !(y.h > need)) return false;
                const double span = std::abs(y.arc - x.arc);
                const double bound = std::min(0.5 * (x.h + y.h) - 0.5 * lipschitz * span, 0.5 * d - span);
                if (bound > need) continue;
                const double mid = 0.5 * (x.u + y.u);
                if (--budget < 0 || mid == x.u || mid == y.u) return false;
                const Sample m = sample(piece, mid);
                stack.push_back({m, y});
                stack.push_back({x, m});
            }
            prev = next;
        }
    }
    return true;
}

// Half of a step, link `front` -> `rear` at that half's end (their places there), the front known
// to stay within `reach` over the half. The health of section 4.1's Proposition 3: if
// R(q_e, a) > d + reach at a place a behind the rear, and the health of the front at q_e exceeds
// reach all along from a to half a link short of q_e, then for every front place q within reach
// of q_e the nearest root behind q is the unique and simple one in (a, q), and it lies before a
// place t_f where R(q_e, t_f) < d - reach. Returns the rear's range [a, t_f], or nullopt.
std::optional<HealthHalf> health_half(const Path& path, const Handle& front, const Handle& rear, double sq, double sr,
                                      double d, const Range& reach_of) {
    const double reach = std::max({sq - reach_of.lo.arc, reach_of.hi.arc - sq, 0.0}) + kHealthSlack;
    if (!(reach < 0.25 * d)) return std::nullopt;
    const double need = reach + kHealthSlack;
    const Vec2 w = front.pos - rear.pos;
    const double c = dot(w, rear.tangent) / norm(w);  // dR/dsigma at the rear
    if (!(c > 0.0)) return std::nullopt;
    // The far end: R exceeds d by `need` a little behind the rear (R grows there at about c).
    const End r{located(rear), sr};
    double back = 2.0 * need / c;
    std::optional<End> a;
    for (int t = 0; t < kTries && back < 0.5 * d; ++t, back *= 2.0) {
        const End p = shifted(path, r, -back);
        if (!(p.arc < sr)) return std::nullopt;
        if (distance(p.at.pos, front.pos) > d + need) {
            a = p;
            break;
        }
    }
    if (!a) return std::nullopt;
    // The rear's far side: R below d by `need` a little ahead of it.
    double ahead = 2.0 * need / c;
    std::optional<End> t_f;
    for (int t = 0; t < kTries; ++t, ahead *= 2.0) {
        const End p = shifted(path, r, ahead);
        if (!(p.arc > sr && p.arc < sq - 0.5 * d)) break;
        if (distance(p.at.pos, front.pos) < d - need) {
            t_f = p;
            break;
        }
    }
    if (!t_f) return std::nullopt;
    // The health from a to half a link short of the front (nearer, R <= d/2 and h >= d/2).
    double short_of = 0.5 * d;
    End near = shifted(path, {located(front), sq}, -short_of);
    for (int t = 0; t < kTries && near.arc < sq - 0.5 * d; ++t) {
        short_of *= 0.99 * 0.5 * d / (sq - near.arc);
        near = shifted(path, {located(front), sq}, -short_of);
    }
    if (!(near.arc >= sq - 0.5 * d && near.arc > sr)) return std::nullopt;
    if (!health_above(path, front.pos, d, a->at.place, near.at.place, need, kSampleBudget)) return std::nullopt;
    return HealthHalf{{*a, *t_f}, std::max(sr - a->arc, t_f->arc - sr), reach};
}

// Whether a rear handle whose front moves forward moves forward too over a half: its speed is
// the front's times cos(alpha) / cos(beta) (section 3), cos(beta) > 0 by its health, and alpha (the
// link's angle with the front's tangent) stays below pi/2 if its value at the half's end, plus
// the tangent's turning over the front's way and the link's own turning (both ends within their
// reaches: at most 2 asin((front + rear reach) / 2d)), does.
bool rear_moves_forward(const Handle& front, const Handle& rear, double d, double front_turning, const HealthHalf& h) {
    const Vec2 u = normalized(front.pos - rear.pos);
    const double alpha = std::abs(math::atan2(cross(u, front.tangent), dot(u, front.tangent)));
    const double y = 0.5 * (h.front_reach + h.rear_reach) / d;
    if (!(y < 1.0)) return false;
    return alpha + front_turning + 2.0 * math::asin(y) < gentle::kMaxLinkTurning;
}

// Half of a step, by turning, the front known only to lie in [f.lo, f.hi] over it (q_e its place
// at the half's end, r_e the rear's): Proposition 1' (Proposition 1 with the front's arc widened).
// If the path from a place r_lo to f.hi turns by less than pi/2, R(f.lo, r_lo) >= d and
// R(f.hi, r_hi) <= d, the rear's root is unique, simple and increasing in the front's place, and
// lies in [r_lo, r_hi]. r_lo and r_hi are guessed from the rear's speed ratio at the end.
std::optional<Range> turning_half(const Path& path, const Handle& front, const Handle& rear, double sq, double sr,
                                  double d, const Range& f, const Calm& calm) {
    const bool calm_front = calm.before > -INFINITY && f.hi.arc <= calm.before;
    const End r{located(rear), sr};
    // The rear moves at about the speed ratio g times the front (section 3): its range is guessed
    // as g times the front's, a little wider (the guesses compound along the chain), then wider.
    const double g = front.speed != 0.0 ? std::abs(rear.speed / front.speed) : 1.0;
    double widen = kFirstWidening;
    for (int t = 0; t < kTries; ++t, widen *= 4.0) {
        const double ratio = g * (1.0 + widen) + widen;
        const End a = shifted(path, r, -(ratio * (sq - f.lo.arc) + kHealthSlack));
        End b = shifted(path, r, ratio * (f.hi.arc - sq) + kHealthSlack);
        if (!(b.arc <= f.hi.arc)) b = f.hi;
        if (!(a.arc <= sr && b.arc >= sr)) return std::nullopt;
        if (!(distance(a.at.pos, f.lo.at.pos) >= d + kHealthSlack) || !(distance(b.at.pos, f.hi.at.pos) <= d - kHealthSlack))
            continue;
        if (!(a.arc > path.s_min()) || !gentle::at_or_ahead(path, f.hi.at.place, a.at.place)) return std::nullopt;
        if (path.turning(a.at.place, f.hi.at.place) < gentle::kMaxLinkTurning) return Range{a, b};
        // Calm: at every front place the rear's root is simple, the nearest, and increasing in
        // the front's place (Proposition 2), so the rear lies between F(f.lo) and F(f.hi);
        // F(f.lo) >= a as R(f.lo, .) rises from 0 to d + slack between f.lo and a, and
        // F(f.hi) <= b as R(f.hi, .) grows going back over [b, f.hi] (turning below pi/2 there).
        if (calm_front && path.turning(b.at.place, f.hi.at.place) < gentle::kMaxLinkTurning) return Range{a, b};
        return std::nullopt;  // a wider guess turns further still
    }
    return std::nullopt;
}

}  // namespace

MotionStepProof prove_motion_step(const Path& path, const BenchSpec& spec, const Frame& lo, const Frame& hi,
                                  const Calm& head, const Calm& body, bool health, bool backing, MotionProofWork& work) {
    MotionStepProof out;
    const size_t handles = std::min(lo.handles.size(), hi.handles.size());
    const Frame* ends[2] = {&lo, &hi};
    // Handle k's whereabouts: `exact` while every link so far passed Proposition 1 or 2 (it stays
    // between its two places); else work.spans[k] (each half's range).
    bool exact = true;
    work.spans.resize(handles);
    for (int e = 0; e < 2; ++e) work.arcs[e].assign(handles, NAN);
    // Handle i's arc position at end e, computed once.
    const auto arc_of = [&](int e, size_t i) {
        double& a = work.arcs[e][i];
        if (std::isnan(a)) a = path.arc(ends[e]->handles[i].place);
        return a;
    };
    for (size_t k = 0; k + 1 < handles; ++k) {
        const Calm& calm = k == 0 ? head : body;
        bool front_exact = false;  // handle k moved forward all the step, though its link fails Propositions 1-2
        const double d = spec.link_after(static_cast<int>(k));
        if (exact) {
            const Place& q0 = lo.handles[k].place;
            const Place& q1 = hi.handles[k].place;
            const Place& r0 = lo.handles[k + 1].place;
            // The front handle stays between q0 and q1 (the induction so far); its computed
            // places must agree (the head's do by construction).
            if (!gentle::at_or_ahead(path, q1, q0)) return {MotionVerdict::backwards, static_cast<int>(k), out.health};
            if (gentle::hull_turns_gently(path, q1, r0, path.turning(r0, q1))) continue;
            // Calm: the front at every moment at or behind q1, itself at or behind the calm stretch's end.
            if (calm.before > -INFINITY && path.arc(q1) <= calm.before) continue;
            if (!health) return {MotionVerdict::turns, static_cast<int>(k), false};
            front_exact = true;
            // From here on, half by half. The head's halves meet at the step's middle; a handle
            // that stayed between its places has them as both halves' range.
            MotionProofWork::Span& s = work.spans[k];
            const End e0{located(lo.handles[k]), arc_of(0, k)}, e1{located(hi.handles[k]), arc_of(1, k)};
            if (k == 0) {
                const End mid = end_at(path, path.at_arc(0.5 * (lo.head_arc + hi.head_arc)));
                s.lo[0] = e0, s.hi[0] = mid;
                s.lo[1] = mid, s.hi[1] = e1;
            } else {
                s.lo[0] = s.lo[1] = e0;
                s.hi[0] = s.hi[1] = e1;
            }
            exact = false;
        }
        MotionProofWork::Span& next = work.spans[k + 1];
        // A front that moved forward all the step (exact until this link) whose link the health
        // proves with the rear moving forward too: the rear then stays between its two places,
        // and the links behind go back to Proposition 1.
        bool forward = front_exact;
        const double front_turning = front_exact ? path.turning(lo.handles[k].place, hi.handles[k].place) : 0.0;
        for (int e = 0; e < 2; ++e) {
            const Handle& front = ends[e]->handles[k];
            const Handle& rear = ends[e]->handles[k + 1];
            const Range f{work.spans[k].lo[e], work.spans[k].hi[e]};
            const double sq = arc_of(e, k), sr = arc_of(e, k + 1);
            std::optional<Range> r = front_exact ? std::nullopt : turning_half(path, front, rear, sq, sr, d, f, calm);
            if (!r) {
                const std::optional<HealthHalf> h = health_half(path, front, rear, sq, sr, d, f);
                if (!h) return {MotionVerdict::turns, static_cast<int>(k), out.health};
                out.health = true;
                r = h->rear;
                forward = forward && rear_moves_forward(front, rear, d, front_turning, *h);
            }
            next.lo[e] = r->lo, next.hi[e] = r->hi;
        }
        if (forward) {
            exact = true;
            continue;
        }
        // Else the links behind are proved over the halves' ranges, if asked.
        if (!backing) return {MotionVerdict::backs, static_cast<int>(k + 1), out.health};
    }
    // The tail's places agree with its moving forward too.
    if (exact && handles > 0 && !gentle::at_or_ahead(path, hi.handles[handles - 1].place, lo.handles[handles - 1].place))
        return {MotionVerdict::backwards, static_cast<int>(handles) - 1, false};
    return out;
}

}  // namespace dragon::jam
