// Rounding as the contest's tables print: six decimals.
#pragma once

namespace dragon {

// Rounds to 6 decimals the way the tables print, without a negative zero.
double round6(double v);

}  // namespace dragon
