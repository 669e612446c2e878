#include "core/make_path.hpp"

#include <cmath>

namespace dragon {

PathBuild make_path(const Scenario& s) {
    constexpr double kTwoPi = 6.283185307179586476925286766559;
    if (s.path.kind == PathKind::spiral) {
        auto spiral = std::make_shared<Spiral>(s.path.pitch);
        const double start = -spiral->length_to(kTwoPi * s.path.start_turn);
        return {spiral, start};
    }
    throw InputError("--path turnaround is not available yet");
}

}  // namespace dragon
