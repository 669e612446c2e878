// The elementary functions the library computes with, the same bits on every platform. The C
// library's sin, cos, atan2, ... differ between implementations in the last bit (glibc's for
// the tool, musl's inside the WebAssembly page), and a bit at the start of a search can move
// the last printed digit of its answer. These are written with IEEE 754's basic operations
// alone (+, -, *, /, sqrt, which every platform rounds the same way; the library is compiled
// with -ffp-contract=off, so no multiply-add is fused on one platform and not on another), so the
// tool, Python and the page print the same digits.
//
// Accuracy (tests/core/test_portable_math.cpp measures it against long double): within 1 ulp
// for sin, cos, tan, atan, hypot, log1p and asinh, 1.5 ulp for atan2 and 2.5 ulp for asin (its
// quotient x / sqrt(1 - x^2) rounded, kept so for speed: asin is the chain solver's most called
// function), over the arguments the library meets (angles up to a million radians; beyond, the
// argument reduction loses accuracy but stays deterministic). Special values (NaN, infinities,
// signed zeros) follow C.
#pragma once

namespace dragon::math {

double sin(double x);               ///< sine of x (radians)
double cos(double x);               ///< cosine of x (radians)
double tan(double x);               ///< tangent of x (radians)
double atan(double x);              ///< arc tangent, in [-pi/2, pi/2]
double atan2(double y, double x);   ///< the angle of (x, y), in [-pi, pi]
double asin(double x);              ///< arc sine, in [-pi/2, pi/2]; NaN outside [-1, 1]
double hypot(double x, double y);   ///< sqrt(x^2 + y^2) without overflow or underflow
double log1p(double x);             ///< log(1 + x), accurate for small x
double asinh(double x);             ///< inverse hyperbolic sine

}  // namespace dragon::math
