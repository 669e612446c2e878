// Film time to simulated time within one shot: a steady rate, or slower near a moment.
#pragma once

#include <optional>
#include <vector>

namespace dragon::film {

// A slow stretch: `rate` within `within` simulated seconds of `at`, easing back to the shot's
// rate over as long again on each side (the logarithm of the rate follows a smoothstep).
struct Slow {
    double at, within, rate;
};

class TimeMap {
public:
    // [from, to] at `rate` simulated seconds per film second (slower near `slow`).
    TimeMap(double from, double to, double rate, std::optional<Slow> slow = {});
    // The steady rate that makes [from, to] last `seconds` of film with `slow` in it.
    static double rate_for(double from, double to, double seconds, const std::optional<Slow>& slow);

    double seconds() const { return total_; }  // film seconds from `from` to `to`
    double time_at(double film_s) const;       // simulated s, clamped to [from, to]
    double film_at(double time) const;         // film s at simulated time (inverse of time_at)
    double rate_at(double time) const;         // simulated s per film s there

private:
    double from_, to_, rate_;
    std::optional<Slow> slow_;
    double total_ = 0;
    std::vector<double> t_, tau_;  // samples of the map where it is not linear
};

}  // namespace dragon::film
