// Progress of a long computation, for a caller that shows it (the CLI's progress line): `done`
// of `total` units of work so far. A computation running on several threads calls it from any of
// them, one call at a time.
#pragma once

#include <cstdint>
#include <functional>

namespace dragon {

// Called with the units of work done so far and the total; may be empty (nobody listening).
using WorkProgress = std::function<void(std::int64_t done, std::int64_t total)>;

}  // namespace dragon
