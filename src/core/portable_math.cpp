#include "dragon/portable_math.hpp"

#include <cmath>
#include <limits>
#include <utility>

// Every function below is a polynomial or a short series evaluated by basic operations, after
// an argument reduction that keeps the series short; the constants are the values they name,
// split into a double and the double nearest the rest (computed to 60 digits with Python's
// decimal module). No operation here depends on the platform: std::fmod, std::frexp, std::ldexp, std::ilogb,
// std::sqrt and std::fabs are exact or correctly rounded by definition.
namespace dragon::math {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// An unevaluated sum hi + lo, |lo| at most half an ulp of hi.
struct Pair {
    double hi, lo;
};

// a + b exactly, as a rounded sum and its error (Knuth's two-sum: any a, b).
Pair two_sum(double a, double b) {
    const double s = a + b;
    const double bb = s - a;
    return {s, (a - (s - bb)) + (b - bb)};
}

// a + b exactly, given |a| >= |b| (or a == 0).
Pair fast_two_sum(double a, double b) {
    const double s = a + b;
    return {s, b - (s - a)};
}

// a * b exactly, as a rounded product and its error (Dekker's: each factor split in halves
// of 26 bits, whose products are exact; |a|, |b| under 2^995).
Pair two_prod(double a, double b) {
    constexpr double kSplitter = 0x1p27 + 1.0;
    const double p = a * b;
    const double ca = kSplitter * a, cb = kSplitter * b;
    const double ah = ca - (ca - a), al = a - ah;
    const double bh = cb - (cb - b), bl = b - bh;
    return {p, ((ah * bh - p) + ah * bl + al * bh) + al * bl};
}

// (n.hi + n.lo) / (d.hi + d.lo), to about 2^-100 relative.
Pair divide(const Pair& n, const Pair& d) {
    const double q = n.hi / d.hi;
    const Pair back = two_prod(q, d.hi);
    const double rest = ((n.hi - back.hi) - back.lo) + n.lo - q * d.lo;  // n.hi - back.hi is exact
    return fast_two_sum(q, rest / d.hi);
}

// sqrt(h.hi + h.lo) as a Pair: the rounded root corrected by one Newton step on the exact rest.
Pair sqrt_pair(const Pair& h) {
    if (h.hi <= 0.0) return {0.0, 0.0};  // nothing to correct at 0 (and no 0 / 0)
    const double root = std::sqrt(h.hi);
    const Pair back = two_prod(root, root);
    return fast_two_sum(root, (((h.hi - back.hi) - back.lo) + h.lo) / (2.0 * root));
}

// pi/2 in three parts: the first two have 33 significant bits, so that n * part is exact for
// |n| < 2^20 (arguments up to about 1.6e6); the third is the rest, to 2^-122.
constexpr double kPio2Part1 = 0x1.921fb54400000p+0;
constexpr double kPio2Part2 = 0x1.0b4611a600000p-34;
constexpr double kPio2Part3 = 0x1.3198a2e037073p-69;
constexpr double kTwoOverPi = 0x1.45f306dc9c883p-1;
constexpr double kPio4 = 0x1.921fb54442d18p-1;
constexpr Pair kPio2{0x1.921fb54442d18p+0, 0x1.1a62633145c07p-54};
constexpr Pair kPi{0x1.921fb54442d18p+1, 0x1.1a62633145c07p-53};
// ln 2 with a first part of 42 bits: k * part is exact for every binary exponent k.
constexpr Pair kLn2{0x1.62e42fefa3800p-1, 0x1.ef35793c76730p-45};
constexpr double kSqrtHalf = 0x1.6a09e667f3bcdp-1;

// v rounded to the nearest whole number (ties to even), for |v| < 2^51: adding 1.5 * 2^52 leaves
// no bits below the unit, and taking it away again is exact. No library call, no rounding mode
// but the default's.
double nearest_whole(double v) {
    constexpr double kShift = 0x1.8p52;
    return (v + kShift) - kShift;
}

// x = n * pi/2 + (r.hi + r.lo), |r| about pi/4 at most; returns n mod 4.
int reduce(double x, Pair& r) {
    const double n = nearest_whole(x * kTwoOverPi);
    const double a = x - n * kPio2Part1;  // exact: n * part1 is exact and close to x
    const Pair s = two_sum(a, -(n * kPio2Part2));
    const Pair t = two_sum(s.hi, -(n * kPio2Part3));
    r = fast_two_sum(t.hi, t.lo + s.lo);
    const int quadrant = static_cast<int>(std::fmod(n, 4.0));  // exact, and defined for any n
    return quadrant < 0 ? quadrant + 4 : quadrant;
}

// The Taylor series of sin and cos, to the term under 2^-60 of the value on |y| <= pi/4 (plus
// the little more reduce() may leave): 1/n! rounded once each, at compile time.
constexpr double inverse_factorial(int n) {
    double f = 1.0;
    for (int k = 2; k <= n; ++k) f *= k;  // exact up to 22!: every factor fits the significand
    return 1.0 / f;
}

// sin(y.hi + y.lo) for |y| <= pi/4 (+ a little), as a Pair.
Pair kernel_sin_pair(const Pair& y) {
    const double z = y.hi * y.hi;
    const double tail = inverse_factorial(5) -
                        z * (inverse_factorial(7) -
                             z * (inverse_factorial(9) -
                                  z * (inverse_factorial(11) -
                                       z * (inverse_factorial(13) -
                                            z * (inverse_factorial(15) - z * inverse_factorial(17))))));
    const double cubic = z * y.hi * (-inverse_factorial(3) + z * tail);
    // sin(hi + lo) = sin(hi) + lo cos(hi), lo being under half an ulp of hi.
    return fast_two_sum(y.hi, cubic + y.lo * (1.0 - 0.5 * z));
}
double kernel_sin(const Pair& y) {
    const Pair s = kernel_sin_pair(y);
    return s.hi + s.lo;
}

// cos(y) - (1 - y^2/2) for z = y^2 <= (pi/4)^2 (+ a little): the series to y^18.
double cos_quartic(double z) {
    return z * z *
           (inverse_factorial(4) -
            z * (inverse_factorial(6) -
                 z * (inverse_factorial(8) -
                      z * (inverse_factorial(10) -
                           z * (inverse_factorial(12) -
                                z * (inverse_factorial(14) - z * (inverse_factorial(16) - z * inverse_factorial(18))))))));
}

// cos(y.hi + y.lo) for |y| <= pi/4 (+ a little): 1 - z/2 rounded, plus what that rounding lost
// ((1 - w) - z/2 is exact), plus the rest; cos(hi + lo) = cos(hi) - lo sin(hi).
double kernel_cos(const Pair& y) {
    const double z = y.hi * y.hi;
    const double half = 0.5 * z;
    const double w = 1.0 - half;
    return w + (((1.0 - w) - half) + (cos_quartic(z) - y.hi * y.lo));
}

// The same as a Pair, with hi^2's own rounding taken too (tan divides two of these).
Pair kernel_cos_pair(const Pair& y) {
    const Pair z = two_prod(y.hi, y.hi);
    const double w = 1.0 - 0.5 * z.hi;
    return fast_two_sum(w, (((1.0 - w) - 0.5 * z.hi) - 0.5 * z.lo) + (cos_quartic(z.hi) - y.hi * y.lo));
}

// atan(t) - t for |t| <= 1/16 (and a little more): the series to t^17.
double atan_tail(double t) {
    const double z = t * t;
    const double s =
        -1.0 / 3 +
        z * (1.0 / 5 + z * (-1.0 / 7 + z * (1.0 / 9 + z * (-1.0 / 11 + z * (1.0 / 13 + z * (-1.0 / 15 + z * (1.0 / 17)))))));
    return t * z * s;
}

// atan(k/8), k = 0..8, as Pairs: the table atan_pair() reduces to.
constexpr Pair kAtanEighths[9] = {
    {0.0, 0.0},
    {0x1.fd5ba9aac2f6ep-4, -0x1.cd37686760c17p-59},
    {0x1.f5b75f92c80ddp-3, 0x1.8ab6e3cf7afbdp-57},
    {0x1.6f61941e4def1p-2, -0x1.c63aae6f6e918p-56},
    {0x1.dac670561bb4fp-2, 0x1.a2b7f222f65e2p-56},
    {0x1.1e00babdefeb4p-1, -0x1.928df287a668fp-58},
    {0x1.4978fa3269ee1p-1, 0x1.2419a87f2a458p-56},
    {0x1.700a7c5784634p-1, -0x1.8c34d25aadef6p-56},
    {0x1.921fb54442d18p-1, 0x1.1a62633145c07p-55},
};

// atan(a) - a for 0 <= a <= 3/16: the series to a^25.
double atan_small_tail(double a) {
    const double z = a * a;
    const double s =
        -1.0 / 3 +
        z * (1.0 / 5 +
             z * (-1.0 / 7 +
                  z * (1.0 / 9 +
                       z * (-1.0 / 11 +
                            z * (1.0 / 13 +
                                 z * (-1.0 / 15 +
                                      z * (1.0 / 17 + z * (-1.0 / 19 + z * (1.0 / 21 + z * (-1.0 / 23 + z / 25))))))))));
    return a * z * s;
}

// atan(a) for 0 <= a <= 1, as a Pair (one rounding from exact): the series itself up to 3/16;
// above, atan(c) + atan((a - c) / (1 + c a)) with c the nearest eighth (at least 1/4), which
// leaves an argument of at most 1/16 whose rounding costs under a fifth of an ulp of the result.
Pair atan_pair(double a) {
    if (a <= 0.1875) return fast_two_sum(a, atan_small_tail(a));
    const int k = static_cast<int>(nearest_whole(a * 8.0));
    const double c = k / 8.0;
    const double t = (a - c) / (1.0 + c * a);  // a - c is exact (Sterbenz)
    const Pair base = kAtanEighths[k];
    return fast_two_sum(base.hi, base.lo + (t + atan_tail(t)));
}

// pi/2 - p and pi - p for a Pair p of at most pi/4, rounded once.
double from_pio2(const Pair& p) {
    const Pair d = two_sum(kPio2.hi, -p.hi);
    return d.hi + (d.lo + (kPio2.lo - p.lo));
}
double from_pi(const Pair& p) {
    const Pair d = two_sum(kPi.hi, -p.hi);
    return d.hi + (d.lo + (kPi.lo - p.lo));
}

// 2 atanh(f) - 2 f for |f| <= 0.1716 (the series to f^23): log((1 + f) / (1 - f)) less its first term.
double log_tail(double f) {
    const double z = f * f;
    const double s =
        1.0 / 3 +
        z * (1.0 / 5 +
             z * (1.0 / 7 +
                  z * (1.0 / 9 +
                       z * (1.0 / 11 +
                            z * (1.0 / 13 + z * (1.0 / 15 + z * (1.0 / 17 + z * (1.0 / 19 + z * (1.0 / 21 + z / 23)))))))));
    return 2.0 * f * z * s;
}

// log(u) + c for u > 0 finite, c a small correction (of u's own rounding): u = 2^k m with m in
// [sqrt(1/2), sqrt(2)), log(m) = 2 atanh((m - 1) / (m + 1)).
double log_of(double u, double c) {
    int k = 0;
    double m = std::frexp(u, &k);
    if (m < kSqrtHalf) m *= 2.0, --k;
    const Pair f = divide({m - 1.0, 0.0}, two_sum(m, 1.0));  // m - 1 is exact (Sterbenz)
    const double kd = k;
    return kd * kLn2.hi + (2.0 * f.hi + (2.0 * f.lo + log_tail(f.hi) + (kd * kLn2.lo + c)));
}

// log(1 + x.hi + x.lo) for |x| < 1/4: 2 atanh(f), f = x / (2 + x) as a Pair.
double log1p_small(const Pair& x) {
    const Pair two_x = two_sum(2.0, x.hi);
    const Pair f = divide(x, fast_two_sum(two_x.hi, two_x.lo + x.lo));
    return 2.0 * f.hi + (2.0 * f.lo + log_tail(f.hi));
}

}  // namespace

double sin(double x) {
    if (!std::isfinite(x)) return x - x;  // NaN for NaN and for infinities
    if (std::fabs(x) < 0x1p-27) return x;  // x - x^3/6 rounds to x (and -0 stays -0)
    if (std::fabs(x) <= kPio4) return kernel_sin({x, 0.0});
    Pair r{};
    switch (reduce(x, r)) {
        case 0: return kernel_sin(r);
        case 1: return kernel_cos(r);
        case 2: return -kernel_sin(r);
        default: return -kernel_cos(r);
    }
}

double cos(double x) {
    if (!std::isfinite(x)) return x - x;
    if (std::fabs(x) < 0x1p-27) return 1.0;
    if (std::fabs(x) <= kPio4) return kernel_cos({x, 0.0});
    Pair r{};
    switch (reduce(x, r)) {
        case 0: return kernel_cos(r);
        case 1: return -kernel_sin(r);
        case 2: return -kernel_cos(r);
        default: return kernel_sin(r);
    }
}

double tan(double x) {
    if (!std::isfinite(x)) return x - x;
    if (std::fabs(x) < 0x1p-27) return x;
    Pair r{x, 0.0};
    const int n = std::fabs(x) <= kPio4 ? 0 : reduce(x, r);
    const Pair s = kernel_sin_pair(r), c = kernel_cos_pair(r);
    const Pair q = n % 2 == 0 ? divide(s, c) : divide(c, s);
    return n % 2 == 0 ? q.hi + q.lo : -(q.hi + q.lo);
}

double atan(double x) {
    if (std::isnan(x)) return x + x;
    const double a = std::fabs(x);
    if (a < 0x1p-27) return x;  // atan x = x - x^3/3 rounds to x
    double r = 0.0;
    if (a <= 1.0) {
        const Pair p = atan_pair(a);
        r = p.hi + p.lo;
    } else if (a > 0x1p60) {
        r = kPio2.hi;  // pi/2 - 1/a rounds to pi/2 (and atan(inf) = pi/2)
    } else {
        r = from_pio2(atan_pair(1.0 / a));
    }
    return std::copysign(r, x);
}

double atan2(double y, double x) {
    if (std::isnan(x) || std::isnan(y)) return x + y;
    const bool left = std::signbit(x);  // x < 0, or x = -0
    if (y == 0.0) return left ? std::copysign(kPi.hi, y) : y;                // +-0 or +-pi
    if (x == 0.0) return std::copysign(kPio2.hi, y);                          // +-pi/2
    if (std::isinf(x) || std::isinf(y)) {                                      // exact directions
        const double angle = std::isinf(x) ? (std::isinf(y) ? (left ? 3.0 * kPio4 : kPio4) : (left ? kPi.hi : 0.0))
                                           : kPio2.hi;
        return std::copysign(angle, y);
    }
    const double ax = std::fabs(x), ay = std::fabs(y);
    double angle = 0.0;
    if (ay <= ax) {
        const Pair p = atan_pair(ay / ax);
        angle = left ? from_pi(p) : p.hi + p.lo;
    } else {
        const Pair p = atan_pair(ax / ay);
        if (left) {  // pi/2 + p, rounded once
            const Pair s = two_sum(kPio2.hi, p.hi);
            angle = s.hi + (s.lo + (kPio2.lo + p.lo));
        } else {
            angle = from_pio2(p);
        }
    }
    return std::copysign(angle, y);
}

double asin(double x) {
    if (std::isnan(x)) return x + x;
    const double a = std::fabs(x);
    if (a > 1.0) return kNaN;
    if (a < 0x1p-27) return x;  // asin x = x + x^3/6 rounds to x
    // asin a = atan(a / c), c = sqrt(1 - a^2) ((1 - a)(1 + a): 1 - a is exact from 1/2 on); above
    // sqrt(1/2), pi/2 - atan(c / a), so that the quotient stays at most 1.
    const double c = std::sqrt((1.0 - a) * (1.0 + a));
    double r = 0.0;
    if (a <= kSqrtHalf) {
        const Pair p = atan_pair(a / c);
        r = p.hi + p.lo;
    } else {
        r = from_pio2(atan_pair(c / a));
    }
    return std::copysign(r, x);
}

double hypot(double x, double y) {
    if (std::isinf(x) || std::isinf(y)) return kInf;
    if (std::isnan(x) || std::isnan(y)) return x + y;
    double a = std::fabs(x), b = std::fabs(y);
    if (a < b) std::swap(a, b);
    if (a == 0.0) return 0.0;
    // Scaled by a power of two (exactly) so that neither square overflows or underflows.
    const int e = std::ilogb(a);
    if (b == 0.0 || e - std::ilogb(b) > 60) return a;  // b^2 is under half an ulp of a^2
    const double as = std::ldexp(a, -e), bs = std::ldexp(b, -e);
    // as^2 + bs^2 as a Pair, its square root corrected once (Newton's step on the exact rest).
    const Pair a2 = two_prod(as, as), b2 = two_prod(bs, bs);
    const Pair sum = two_sum(a2.hi, b2.hi);
    const Pair h = fast_two_sum(sum.hi, sum.lo + a2.lo + b2.lo);
    const Pair root = sqrt_pair(h);
    return std::ldexp(root.hi + root.lo, e);
}

double log1p(double x) {
    if (std::isnan(x) || x == kInf) return x + x;
    if (x < -1.0) return kNaN;
    if (x == -1.0) return -kInf;
    if (std::fabs(x) < 0x1p-54) return x;
    if (std::fabs(x) < 0.25) {
        // log(1 + x) = 2 atanh(f), f = x / (2 + x) as a Pair, with no rounding of 1 + x.
        return log1p_small({x, 0.0});
    }
    const double u = 1.0 + x;
    // What rounding 1 + x lost, as a correction to log(u): log(u + d) = log(u) + d / u.
    const double c = u < 0x1p53 ? (x - (u - 1.0)) / u : 0.0;
    return log_of(u, c);
}

double asinh(double x) {
    if (!std::isfinite(x)) return x + x;
    const double a = std::fabs(x);
    if (a < 0x1p-27) return x;  // asinh x = x - x^3/6 rounds to x
    double r = 0.0;
    if (a > 0x1p28) {
        r = log_of(a, 0.0) + kLn2.hi + kLn2.lo;  // log(2a): sqrt(a^2 + 1) = a to double precision
    } else if (a >= 0.125) {
        // log(a + sqrt(a^2 + 1)), the sum (at least 1.13) as a Pair.
        const Pair a2 = two_prod(a, a);
        const Pair one_a2 = two_sum(1.0, a2.hi);
        const Pair root = sqrt_pair(fast_two_sum(one_a2.hi, one_a2.lo + a2.lo));
        const Pair u = two_sum(a, root.hi);
        const Pair sum = fast_two_sum(u.hi, u.lo + root.lo);
        r = log_of(sum.hi, sum.lo / sum.hi);
    } else {
        // asinh a = log(1 + a + (sqrt(a^2 + 1) - 1)) = log1p(a + a^2 / (1 + sqrt(1 + a^2))).
        const double a2 = a * a;
        const Pair v = two_sum(a, a2 / (1.0 + std::sqrt(1.0 + a2)));
        // log1p(v.hi + v.lo) = log1p(v.hi) + v.lo / (1 + v.hi).
        r = log1p_small(v);  // v < 0.125 + 0.008
    }
    return std::copysign(r, x);
}

}  // namespace dragon::math
