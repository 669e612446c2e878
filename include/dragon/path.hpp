// Paths the head travels along, parameterised by arc length in the direction of travel.
//
// A path is a chain of pieces (one for the plain spiral; coil-in spiral, two arcs and the
// coil-out spiral for the turnaround). Each piece has its own natural parameter u (the polar
// angle theta on a spiral, the angle about the centre on an arc); a Place names the piece and u,
// so hot loops never convert to arc length and back. Arc position s grows in the direction
// of travel; the handles of the chain sit at smaller s than the head.
#pragma once

#include <cmath>
#include <memory>
#include <optional>
#include <utility>

#include "dragon/geometry.hpp"
#include "dragon/portable_math.hpp"

namespace dragon {

// A place on a path: which piece, and the piece's own parameter there.
struct Place {
    int piece = 0;   // 0 .. piece_count() - 1, in travel order
    double u = 0.0;  // the piece's parameter: theta on a spiral, the angle about the centre on an arc (rad)
};

// What a spiral's chord solver learned placing this point, kept for the next link: the angle
// the chord spanned, the cos and sin of its half (which must belong to that angle: the solver
// builds on them), the predicted change of the angle for the next link of the same length, and
// the rate the angle changed at along the spiral (d angle / d theta, when `sloped`), from which
// the link after next predicts to second order. Only a first guess: the next solve uses it only
// at the place it was made (theta) and for the same chord, and reaches the same root from any
// consistent guess (Chain.TheChordMemoIsOnlyAGuess). Empty (chord 0) everywhere else.
struct ChordMemo {
    double theta = 0.0;     // rad: the place it was made at
    double chord = 0.0;     // m: the chord it solved (0: empty)
    double angle = 0.0;     // rad: the angle the chord spanned
    double cos_half = 1.0;  // cos(angle / 2)
    double sin_half = 0.0;  // sin(angle / 2)
    double drift = 0.0;     // rad: the predicted change of `angle` for the next link
    double slope = 0.0;     // d angle / d theta where the last step began (valid when `sloped`)
    bool sloped = false;    // `slope` was measured (the second-order prediction may use it)
};

// A place with its point and unit tangent (pointing in the direction of travel).
struct Located {
    Place place;                  // where
    Vec2 pos = Vec2::Zero();      // m
    Vec2 tangent = Vec2::Zero();  // unit
    ChordMemo memo{};             // what the chord solver learned placing it (empty but on a spiral)
};

class Spiral;

// A path the head follows: pieces joined end to end, each with its own parameter u, measured
// by arc position s (m) in the direction of travel.
class Path {
public:
    virtual ~Path() = default;

    // The point and unit tangent at a place.
    virtual Located at(Place p) const = 0;
    // Arc position of a place, and its inverse. at_arc requires s_min() <= s <= s_max().
    virtual double arc(Place p) const = 0;
    virtual Located at_arc(double s) const = 0;
    virtual double s_min() const = 0;  // may be -infinity
    virtual double s_max() const = 0;  // may be +infinity
    // Signed curvature at a place (positive when the path turns counter-clockwise).
    virtual double curvature(Place p) const = 0;
    // Total absolute turning of the tangent from `rear` to `front` (rear not ahead of front),
    // rad: the integral of |curvature| over the arc between them.
    virtual double turning(Place rear, Place front) const = 0;
    // Where the path's curvature stays small, for certifying whole stretches of motion at once.
    // curvature_bounded_before(k): the largest arc position s such that |curvature| <= k at every
    // place at or behind s (+infinity if everywhere; -infinity if nowhere). Requires k > 0.
    // curvature_bounded_after(k): the smallest s such that |curvature| <= k at every place at or
    // ahead of s (-infinity if everywhere; +infinity if nowhere).
    virtual double curvature_bounded_before(double k) const = 0;
    virtual double curvature_bounded_after(double k) const = 0;
    // The pieces in travel order (Place::piece): how many, the arc position where piece k begins
    // (-infinity for the first), and the least and largest |curvature| on it.
    virtual int piece_count() const { return 1; }
    virtual double piece_begin(int piece) const = 0;
    // The piece's parameter u where it begins and where it ends, in travel order (infinite for
    // an endless piece).
    virtual std::pair<double, double> piece_span(int piece) const = 0;
    // The least and largest |curvature| on the piece, 1/m.
    virtual std::pair<double, double> curvature_span(int piece) const = 0;

    // The nearest place behind `from` (largest s' < s(from)) whose straight-line distance
    // from from.pos is exactly `chord`; nullopt when the path ends first.
    virtual std::optional<Located> behind(const Located& from, double chord) const = 0;
    // The spiral r = b theta about the origin, travelled inward with u = theta, on which p and
    // every place behind it lie (the plain spiral itself; the turnaround's coil-in piece), or
    // null: there a chain behind p moves as on the plain spiral, and the path's curvature keeps
    // one sign, its magnitude falling going back.
    virtual const Spiral* coil_in_spiral(Place) const { return nullptr; }
};

// The Archimedean spiral r = b theta, b = pitch / 2pi, travelled inward (clockwise, theta
// decreasing) and ending at the centre. u = theta; s = -L(theta), where
// L(theta) = (b/2) (theta sqrt(1 + theta^2) + asinh theta) is the arc length from the centre.
class Spiral final : public Path {
public:
    explicit Spiral(double pitch);  // m between turns, > 0 (not checked here: validate() checks a scenario's)

    double pitch() const { return pitch_; }  // m
    double b() const { return b_; }          // pitch / 2pi, m per radian

    Located at(Place p) const override;
    double arc(Place p) const override;
    Located at_arc(double s) const override;
    double s_min() const override;
    double s_max() const override { return 0.0; }
    double curvature(Place p) const override;
    double turning(Place rear, Place front) const override;
    double curvature_bounded_before(double k) const override;
    double curvature_bounded_after(double k) const override;
    double piece_begin(int) const override { return s_min(); }
    std::pair<double, double> piece_span(int) const override { return {INFINITY, 0.0}; }
    std::pair<double, double> curvature_span(int) const override { return {0.0, 2.0 / b_}; }
    std::optional<Located> behind(const Located& from, double chord) const override;
    const Spiral* coil_in_spiral(Place) const override { return this; }

    // Curvature magnitude at theta, and the theta where it equals k (it falls as theta grows:
    // 2 / b at the centre, about 1 / (b theta) far out); 0 when k >= 2 / b.
    double curvature_at(double theta) const;
    double theta_of_curvature(double k) const;
    // The tangent's direction angle at theta up to a constant, rad: theta + atan(theta). It grows
    // with theta, and its change between two places is the turning between them.
    static double tangent_angle(double theta) { return theta + math::atan(theta); }

    // Arc length from the centre to theta, and its inverse (safeguarded Newton).
    double length_to(double theta) const;
    double theta_at_length(double length) const;

private:
    // behind(), when the chord cannot reach round past the far side (one root within half a
    // turn: Halley's method), and when it can (a march that cannot step over a root).
    std::optional<Located> behind_within_half_turn(const Located& from, double chord) const;
    std::optional<Located> behind_round_the_centre(const Located& from, double chord) const;

    double pitch_;
    double b_;
};

}  // namespace dragon
