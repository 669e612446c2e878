// The chain solver: from the head's arc position, every handle on the path and its exact speed.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "dragon/geometry.hpp"
#include "dragon/path.hpp"
#include "dragon/scenario.hpp"
#include "dragon/valid_motion.hpp"

namespace dragon {

// A handle (the peg joining two benches) at one instant.
struct Handle {
    Vec2 pos = Vec2::Zero();      // m
    Vec2 tangent = Vec2::Zero();  // unit tangent of the path at the handle, direction of travel
    double speed;   // m/s, exact (rigid-link projection)
    Place place;    // where on the path: piece and parameter, for the next link's solve
};

// One instant: handles 0..N (0 = head front) and benches 1..N stored at index 0..N-1.
struct Frame {
    double time = 0.0;            // s
    double head_arc = 0.0;        // m: the head front handle's arc position on the path
    std::vector<Handle> handles;  // N + 1, head front first
    std::vector<Rect> benches;    // N, bench 1 (the head) first
};

// Fills `out` with the chain whose head front handle is at arc position head_arc moving at
// head_speed. Each next handle is the nearest point behind the previous one at its link's
// chord. Speeds follow from rigidity: both ends of a link have equal velocity components along
// it, v_i (T_i . u) = v_{i+1} (T_{i+1} . u). Throws SolverError if the chain runs off the path.
void solve_chain(const Path& path, const BenchSpec& spec, double head_arc, double head_speed,
                 Frame& out);

// The rectangle of bench k (1..N) from its two handles.
Rect bench_rect(const BenchSpec& spec, int bench, const Vec2& front, const Vec2& rear);

// The stretch of time over which the dragon follows its path (dragon/valid_motion.hpp).
struct ValidRange {
    double from = 0.0;          // s: the motion is continuous on [from, to]
    double to = 0.0;            // s
    double from_travel = 0.0;   // m of head travel: the same range
    double to_travel = 0.0;     // m
    std::optional<Jam> before;  // what ends it before t = 0; nullopt: the path's end, or never
    std::optional<Jam> after;   // what ends it after t = 0; nullopt: the path's end, or never
};

// A scenario made runnable: its path, and the head's arc position as a function of time.
// The motion is anchored at t = 0: it is valid from there on, forwards and backwards, until a
// handle would have to jump. Frames are refused outside that range.
//
// The chain's shape depends only on how far the head has travelled from where it is at t = 0;
// the head's speed sets the clock, t = travel / speed. Everything a Simulation searches for (the
// end of its valid motion here; first contacts, clearances and speed ratios in the analyses) is
// searched in travel, so it is the same event, bit for bit, at any head speed.
class Simulation {
public:
    // Throws InputError (a ScenarioError) for a scenario validate() refuses.
    explicit Simulation(const Scenario& s);

    const Scenario& scenario() const { return scenario_; }              // as given
    const Path& path() const { return *path_; }                         // the path the head follows
    std::shared_ptr<const Path> shared_path() const { return path_; }  // the same, to keep (a Scene's guides)

    // Arc position of the head front handle at time t (t = 0: the start, or on the
    // turnaround path the moment the head begins the turn).
    double head_arc(double t) const { return start_arc_ + scenario_.head_speed * t; }
    double start_arc() const { return start_arc_; }  // head_arc(0), m
    // The head's travel from its place at t = 0 by time t, m, and the time of a travel, s.
    double travel(double t) const { return scenario_.head_speed * t; }
    double time_of(double travel) const { return travel / scenario_.head_speed; }
    // The same motion with the head at another speed (throws InputError for a speed that is not
    // a finite number > 0): every frame the same at every travel, the valid range the same in
    // travel, and shared, so that what either has searched the other knows.
    Simulation at_speed(double head_speed) const;
    // The latest time the head stays on the path (the spiral's centre; +inf on the turnaround).
    double end_time() const;

    // Throws InputError (its key `what`, e.g. Key::to) unless the head is on the path at time t
    // and the whole chain within kMaxReach of the spiral's centre (the turnaround path is endless,
    // but far out its points lose precision).
    void require_on_path(double t, Key what) const;
    // travel(t), for a t within the valid motion (or at its end) kept within it in travel too:
    // the time of a jam, converted back, may round one step past the jam's travel.
    double travel_within(double t) const;

    // The whole valid range: searched once, on first use (a few milliseconds), then kept (copies
    // of a Simulation share it).
    ValidRange valid_range() const;
    // The jam met between t = 0 and t (on either side of 0), if any. Searches only as far as t
    // needs, and remembers how far it has looked.
    std::optional<Jam> jam_before(double t) const;
    // The same for a head travel x, m.
    std::optional<Jam> jam_before_travel(double x) const;
    // require_on_path, and throws InputError naming the jam if t lies past one.
    void require_valid(double t, Key what) const;
    // The same for a head travel x, m (PastTheValidMotion names the time x / speed).
    void require_valid_travel(double x, Key what) const;
    // The latest time the motion is valid: valid_range().to.
    double valid_end() const { return valid_range().to; }
    // [t0, t1] cut to the valid motion, and the jam that cut it (the later end's, if both did).
    // Throws InputError (naming from_what or to_what) when an end lies off the path or the
    // range holds no valid moment.
    struct Span {
        double from;             // s
        double to;               // s
        std::optional<Jam> jam;  // the jam that cut it, if one did
    };
    // [t0, t1], s, as a Span.
    Span clip_to_valid(double t0, double t1, Key from_what, Key to_what) const;
    // The same for a range of head travel [x0, x1], m, with the jam at each end that cut it, and
    // cut at the spiral's centre too.
    struct TravelSpan {
        double from;                // m of head travel
        double to;                  // m of head travel
        std::optional<Jam> before;  // the jam that cut its start
        std::optional<Jam> after;   // the jam that cut its end
    };
    // [x0, x1], m, as a TravelSpan.
    TravelSpan clip_travel(double x0, double x1, Key from_what, Key to_what) const;

    // The chain at time t; throws InputError unless t is within the valid range (require_valid).
    Frame frame(double t) const;
    void frame_into(double t, Frame& out) const;
    // The chain at head travel x, m (frame.time = x / speed): the same positions at any speed.
    Frame frame_at_travel(double x) const;
    void frame_at_travel_into(double x, Frame& out) const;

    // The same motion with only benches 1..k solved (k clamped to 1..bench_count): their frames
    // are the leading part of this one's, at a fraction of the cost. Its valid range stays this
    // chain's (shared with this simulation), though the benches ahead alone might go farther.
    Simulation leading(int k) const;
    // How many benches a frame holds: bench_count, or k for leading(k).
    int solved_benches() const { return solved_ > 0 ? solved_ : scenario_.bench.bench_count; }

private:
    struct Validity;  // what the searches have found so far, shared by copies
    // The jam on one side of t = 0 (forward: ahead), after its walk has reached head arc s (or
    // the side's end when `whole`); nullopt if none found there.
    std::optional<Jam> side_jam(double s, bool forward, bool whole) const;
    bool arc_on_path(double s) const;  // require_arc_on_path would pass
    void require_arc_on_path(double s, Key what, const std::string& value) const;

    Scenario scenario_;
    std::shared_ptr<const Path> path_;
    double start_arc_ = 0.0;
    double entry_length_ = 0.0;  // turnaround: arc length from the centre to where the turn starts
    std::shared_ptr<Validity> validity_;
    int solved_ = 0;  // benches a frame holds, 0: all (leading())
};

// One line for a message: what happens to which handle at the jam.
std::string describe(const Jam& j);
// v with as many decimals as `resolution` (how closely v is known) supports, at most 9: 9 for 1e-10.
std::string format_resolved(double v, double resolution);
// "the dragon can follow its path only until t = 432.917924228 s, where handle 1 can no longer
// follow handle 0: ..." (from instead of until for a jam behind t = 0). Every command words a
// jam with this one sentence.
std::string jam_sentence(const Jam& j);

// A moment past the end of the valid motion (Simulation::require_valid): the field and time,
// and the jam, for an application to word (allowed() words it in the library's terms).
struct PastTheValidMotion : InputError {
    // The moment t, s, under `field`, past the jam j.
    PastTheValidMotion(Key field, double t, const Jam& j);
    // The same for a value as given ("120 m" of head travel, say).
    PastTheValidMotion(Key field, const std::string& value, const Jam& j);
    Jam jam;     // the end of the valid motion it lies past
    bool ahead;  // jam.ahead: the motion is valid until it, else from it
};

}  // namespace dragon
