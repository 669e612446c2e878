// When the head reaches the turning space's boundary (analyses.hpp).
#include "dragon/analyses.hpp"
#include "dragon/turnaround.hpp"

namespace dragon {

double boundary_travel(const Simulation& sim) {
    const Scenario& s = sim.scenario();
    // On the turnaround path the turn begins on the boundary, at t = 0 by definition.
    if (s.path.kind == PathKind::turnaround) return 0.0;
    const auto* spiral = dynamic_cast<const Spiral*>(&sim.path());
    if (!spiral) throw SolverError("boundary_travel: a plain-spiral scenario whose path is not a Spiral");
    // The head's arc position is -L(theta) on the spiral: theta = turn_radius / b there.
    return -spiral->length_to(s.path.turn_radius / spiral->b()) - sim.start_arc();
}

double boundary_time(const Simulation& sim) { return sim.time_of(boundary_travel(sim)); }

}  // namespace dragon
