#include "time_map.hpp"

#include <algorithm>
#include <cmath>

namespace dragon::film {

namespace {
// Samples of a slowed map: its rate changes over `within` at the least, so 4000 samples over
// the shot resolve it to far below a frame in any shot a film would show.
constexpr int samples = 4000;

double rate_of(double t, double rate, const std::optional<Slow>& slow) {
    if (!slow) return rate;
    const double d = std::abs(t - slow->at) - slow->within;  // distance past the slow stretch
    double w = 1.0;
    if (d > slow->within) w = 0.0;
    else if (d > 0) {
        const double x = 1.0 - d / slow->within;
        w = x * x * (3 - 2 * x);
    }
    return std::exp((1 - w) * std::log(rate) + w * std::log(slow->rate));
}
}  // namespace

TimeMap::TimeMap(double from, double to, double rate, std::optional<Slow> slow)
    : from_(from), to_(to), rate_(rate), slow_(slow) {
    if (!slow_) {
        total_ = (to - from) / rate;
        return;
    }
    t_.resize(samples + 1);
    tau_.resize(samples + 1);
    const double h = (to - from) / samples;
    t_[0] = from;
    tau_[0] = 0;
    for (int i = 1; i <= samples; ++i) {
        t_[i] = i == samples ? to : from + i * h;
        // Simpson's rule on each step: the rate is smooth within one.
        const double a = t_[i - 1], b = t_[i];
        tau_[i] = tau_[i - 1] + (b - a) / 6 *
                                    (1 / rate_of(a, rate, slow_) + 4 / rate_of(0.5 * (a + b), rate, slow_) +
                                     1 / rate_of(b, rate, slow_));
    }
    total_ = tau_.back();
}

double TimeMap::rate_for(double from, double to, double seconds, const std::optional<Slow>& slow) {
    if (!slow) return (to - from) / seconds;
    // Film seconds fall as the rate rises: bisect its logarithm.
    double lo = std::log(1e-9), hi = std::log(1e12);
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        if (TimeMap(from, to, std::exp(mid), slow).seconds() > seconds) lo = mid;
        else hi = mid;
    }
    return std::exp(0.5 * (lo + hi));
}

double TimeMap::time_at(double film_s) const {
    if (film_s <= 0) return from_;
    if (film_s >= total_) return to_;
    if (!slow_) return std::min(to_, from_ + rate_ * film_s);
    const auto it = std::upper_bound(tau_.begin(), tau_.end(), film_s);
    const std::size_t i = static_cast<std::size_t>(it - tau_.begin());
    const double f = (film_s - tau_[i - 1]) / (tau_[i] - tau_[i - 1]);
    return t_[i - 1] + f * (t_[i] - t_[i - 1]);
}

double TimeMap::film_at(double time) const {
    if (time <= from_) return 0;
    if (time >= to_) return total_;
    if (!slow_) return (time - from_) / rate_;
    const auto it = std::upper_bound(t_.begin(), t_.end(), time);
    const std::size_t i = static_cast<std::size_t>(it - t_.begin());
    const double f = (time - t_[i - 1]) / (t_[i] - t_[i - 1]);
    return tau_[i - 1] + f * (tau_[i] - tau_[i - 1]);
}

double TimeMap::rate_at(double time) const { return rate_of(time, rate_, slow_); }

}  // namespace dragon::film
