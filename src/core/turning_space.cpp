// When the head reaches the turning space.
#include "dragon/analyses.hpp"

namespace dragon {

double boundary_time(const Simulation& sim) {
    const Scenario& s = sim.scenario();
    if (s.path.kind == PathKind::turnaround) return 0.0;
    const auto& spiral = static_cast<const Spiral&>(sim.path());
    const double theta = s.path.turn_radius / spiral.b();
    return (-spiral.length_to(theta) - sim.start_arc()) / s.head_speed;
}

}  // namespace dragon
