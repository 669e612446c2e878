// The chain solver: from the head's arc position, every handle on the path and its exact speed.
#pragma once

#include <memory>
#include <vector>

#include "dragon/geometry.hpp"
#include "dragon/path.hpp"
#include "dragon/scenario.hpp"

namespace dragon {

struct Handle {
    Vec2 pos;
    Vec2 tangent;   // unit tangent of the path at the handle, direction of travel
    double speed;   // m/s, exact (rigid-link projection)
    Place place;
};

// One instant: handles 0..N (0 = head front) and benches 1..N stored at index 0..N-1.
struct Frame {
    double time = 0.0;
    double head_arc = 0.0;
    std::vector<Handle> handles;
    std::vector<Rect> benches;
};

// Fills `out` with the chain whose head front handle is at arc position head_arc moving at
// head_speed. Each next handle is the nearest point behind the previous one at its link's
// chord. Speeds follow from rigidity: both ends of a link have equal velocity components along
// it, v_i (T_i . u) = v_{i+1} (T_{i+1} . u). Throws InputError if the chain runs off the path.
void solve_chain(const Path& path, const BenchSpec& spec, double head_arc, double head_speed,
                 Frame& out);

// The rectangle of bench k (1..N) from its two handles.
Rect bench_rect(const BenchSpec& spec, int bench, Vec2 front, Vec2 rear);

// A scenario made runnable: its path, and the head's arc position as a function of time.
class Simulation {
public:
    explicit Simulation(const Scenario& s);

    const Scenario& scenario() const { return scenario_; }
    const Path& path() const { return *path_; }
    std::shared_ptr<const Path> shared_path() const { return path_; }

    // Arc position of the head front handle at time t (t = 0: the start, or on the
    // turnaround path the moment the head begins the turn).
    double head_arc(double t) const { return start_arc_ + scenario_.head_speed * t; }
    double start_arc() const { return start_arc_; }
    // The latest time the head stays on the path (the spiral's centre; +inf on the turnaround).
    double end_time() const;

    // Throws InputError (naming `what`, e.g. "--to") unless the head is on the path at time t
    // and the whole chain within kMaxReach of the spiral's centre (the turnaround path is endless,
    // but far out its points lose precision).
    void require_on_path(double t, const char* what) const;

    Frame frame(double t) const;
    void frame_into(double t, Frame& out) const;

private:
    Scenario scenario_;
    std::shared_ptr<const Path> path_;
    double start_arc_ = 0.0;
    double entry_length_ = 0.0;  // turnaround: arc length from the centre to where the turn starts
};

}  // namespace dragon
