// The elementary functions the library computes with, the same bits on every platform. The C
// library's sin, cos, atan2, ... differ between implementations in the last bit (glibc's for
// the tool, musl's inside the WebAssembly page), and a bit at the start of a search can move
// the last printed digit of its answer. These are written with IEEE 754's basic operations
// alone (+, -, *, /, sqrt, which every platform rounds the same way; the library is compiled
// with -ffp-contract=off, so no multiply-add is fused on one platform and not on another), so the
// tool, Python and the page print the same digits.
//
// Accuracy (tests/core/test_portable_math.cpp measures it against long double): within 1 ulp
// for every function, over the arguments the library meets (angles up to a million radians;
// beyond, the argument reduction loses accuracy but stays deterministic). Special values (NaN,
// infinities, signed zeros) follow C.
#pragma once

namespace dragon::math {

double sin(double x);
double cos(double x);
double tan(double x);
double atan(double x);
double atan2(double y, double x);
double asin(double x);
double hypot(double x, double y);
double log1p(double x);
double asinh(double x);

}  // namespace dragon::math
