#include "dragon/constants.hpp"
#include "make_path.hpp"

#include <cmath>

#include "dragon/turnaround.hpp"

namespace dragon {

PathBuild make_path(const Scenario& s) {
    if (s.path.kind == PathKind::spiral) {
        auto spiral = std::make_shared<Spiral>(s.path.pitch);
        const double start = -spiral->length_to(kTwoPi * s.path.start_turn);
        return {spiral, start};
    }
    // The turnaround path's arc position is 0 where the head enters arc 1: t = 0 there.
    auto path = std::make_shared<TurnaroundPath>(design_s_curve(s));
    return {path, path->join_arc(1)};
}

}  // namespace dragon
