// Closed intervals of reals for the proofs' bounds (handle_accel, shape_rates), evaluated in
// round-to-nearest: what an operation loses to rounding (a few ulps of each bound) each caller's
// final widening covers (its relative slack, far above a few dozen operations' ulps).
#pragma once

#include <algorithm>
#include <cmath>

namespace dragon::contact {

struct Iv {
    double lo, hi;
};
inline Iv operator+(Iv a, Iv b) { return {a.lo + b.lo, a.hi + b.hi}; }
inline Iv operator+(double s, Iv a) { return {s + a.lo, s + a.hi}; }
inline Iv operator-(Iv a, Iv b) { return {a.lo - b.hi, a.hi - b.lo}; }
inline Iv operator-(Iv a) { return {-a.hi, -a.lo}; }
inline Iv operator*(Iv a, Iv b) {
    const double p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
    return {std::min({p[0], p[1], p[2], p[3]}), std::max({p[0], p[1], p[2], p[3]})};
}
inline Iv operator*(double s, Iv a) { return s >= 0.0 ? Iv{s * a.lo, s * a.hi} : Iv{s * a.hi, s * a.lo}; }
// b strictly positive (callers check b.lo > 0).
inline Iv operator/(Iv a, Iv b) { return a * Iv{1.0 / b.hi, 1.0 / b.lo}; }
// a^2, which is never negative (a * a would let an interval holding 0 go below it).
inline Iv square(Iv a) {
    const double l = a.lo * a.lo, h = a.hi * a.hi;
    if (a.lo <= 0.0 && a.hi >= 0.0) return {0.0, std::max(l, h)};
    return {std::min(l, h), std::max(l, h)};
}
inline double magnitude(Iv a) { return std::max(std::abs(a.lo), std::abs(a.hi)); }

}  // namespace dragon::contact
