#include "dragon/decimals.hpp"

#include <cmath>

namespace dragon {

double round6(double v) {
    const double r = std::round(v * 1e6) / 1e6;
    return r == 0.0 ? 0.0 : r;  // no "-0.000000"
}

}  // namespace dragon
