// Bounds on each handle's rates in the head's turned frame over a cell (shape_rates.hpp).
#include "shape_rates.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "interval.hpp"
#include "dragon/portable_math.hpp"

namespace dragon::contact {

namespace {

// Relative and absolute (1/m) widening of each bound: the interval arithmetic's rounding (a few
// ulps of each of a few dozen operations a link, compounded over the chain's links at a factor
// |1 + b A_rho| below 1) is far below the relative one; the chains' own error (angles to
// ~1e-14 rad, moving each interval's ends by as little) far below both.
constexpr double kRateRelativeSlack = 1e-9;
constexpr double kRateAbsoluteSlack = 1e-12;

double widen(double bound) { return bound * (1.0 + kRateRelativeSlack) + kRateAbsoluteSlack; }

}  // namespace

bool shape_rate_bounds(const Frame& least, const Frame& most, double b_lo, double b_hi, std::vector<double>& speed,
                       std::vector<double>& accel) {
    const size_t nh = std::min(least.handles.size(), most.handles.size());
    speed.resize(nh);
    accel.resize(nh);
    if (nh == 0) return true;
    // The head: P_0 = (r0, 0), so P_0' = (1, 0) and P_0'' = 0.
    speed[0] = 1.0;
    accel[0] = 0.0;
    const Iv b{b_lo, b_hi};
    Iv rate{0.0, 0.0}, bend{0.0, 0.0};  // D_m' and D_m'' of the handle in front
    // Each handle's radius over the cell: least in `most` at b_lo, largest in `least` at b_hi.
    const auto radius = [&](size_t m) { return Iv{b_lo * most.handles[m].place.u, b_hi * least.handles[m].place.u}; };
    for (size_t m = 0; m + 1 < nh; ++m) {
        const double a_lo = least.handles[m + 1].place.u - least.handles[m].place.u;
        const double a_hi = most.handles[m + 1].place.u - most.handles[m].place.u;
        if (!(a_lo > 0.0) || !(a_hi < 0.5 * std::numbers::pi) || !(a_lo <= a_hi)) return false;
        const Iv rho = radius(m), alpha{a_lo, a_hi};
        // sin rises and cos falls on (0, pi/2): each at the span's two ends.
        const Iv sin_a{math::sin(a_lo), math::sin(a_hi)}, cos_a{math::cos(a_hi), math::cos(a_lo)};
        const Iv vers{1.0 - cos_a.hi, 1.0 - cos_a.lo};  // 1 - cos(alpha)
        const Iv rear = rho + b * alpha;                // the rear handle's radius
        // F's partial derivatives, each written as a sum of terms of one sign where it can be.
        const Iv f_a = 2.0 * (b * (rho * vers + b * alpha)) + 2.0 * (rho * rear * sin_a);
        if (!(f_a.lo > 0.0)) return false;
        const Iv f_r = 2.0 * ((rho + rear) * vers);
        const Iv f_rr = 4.0 * vers;
        const Iv f_ra = 2.0 * (b * vers) + 2.0 * ((rho + rear) * sin_a);
        const Iv f_aa = 2.0 * square(b) + 4.0 * (b * rho * sin_a) + 2.0 * (rho * rear * cos_a);
        const Iv a_r = -(f_r / f_a);
        const Iv a_rr = -((f_rr + 2.0 * (f_ra * a_r) + f_aa * square(a_r)) / f_a);
        const Iv grow = 1.0 + b * a_r;
        const Iv next_bend = bend * grow + a_rr * square(1.0 + b * rate);
        rate = rate * grow + a_r;
        bend = next_bend;
        // Handle m + 1: P' and P'' from its radius's interval and D', D''.
        const Iv rho1 = radius(m + 1), rho1_rate = 1.0 + b * rate;
        speed[m + 1] = widen(std::hypot(magnitude(rho1_rate), magnitude(rho1 * rate)));
        const Iv along = b * bend - rho1 * square(rate), across = 2.0 * (rho1_rate * rate) + rho1 * bend;
        accel[m + 1] = widen(std::hypot(magnitude(along), magnitude(across)));
    }
    return true;
}

}  // namespace dragon::contact
