// Golden-section search: the least value of f on [a, b], for f unimodal there (kinks allowed, no
// derivative used). Each round keeps the part of the bracket holding the lesser of two probes
// and probes once more, shrinking it by the golden ratio; it stops when the bracket is no wider
// than `tolerance` (or after `max_rounds`, a cap that only turns a bug into an answer instead of
// a hang). `less` orders f's values, so f may return a struct (a pair of benches with their
// distance). Returns the better of the last two probes: its place and its value.
#pragma once

#include <cmath>
#include <functional>
#include <utility>

namespace dragon {

template <class F, class Less = std::less<>>
auto golden_min(F&& f, double a, double b, double tolerance, Less less = {}, int max_rounds = 300)
    -> std::pair<double, decltype(f(a))> {
    const double g = 0.5 * (std::sqrt(5.0) - 1.0);
    double x1 = b - g * (b - a), x2 = a + g * (b - a);
    auto f1 = f(x1), f2 = f(x2);
    for (int round = 0; round < max_rounds && b - a > tolerance; ++round) {
        if (!less(f2, f1)) {  // f1 <= f2: the least lies in [a, x2]
            b = x2, x2 = x1, f2 = f1;
            x1 = b - g * (b - a), f1 = f(x1);
        } else {
            a = x1, x1 = x2, f1 = f2;
            x2 = a + g * (b - a), f2 = f(x2);
        }
    }
    if (!less(f2, f1)) return {x1, f1};
    return {x2, f2};
}

}  // namespace dragon
