// Rounding as the contest's tables print (six decimals), and times as every message prints them.
#pragma once

#include <string>

namespace dragon {

// Rounds to 6 decimals the way the tables print, without a negative zero.
double round6(double v);
// A time without binary noise: "300", "-100", "0.1", "412.4738" (to 1e-9 s at most).
std::string format_time(double t);

}  // namespace dragon
