// A scenario: the dragon's benches, the path it follows and how fast its head moves.
// Contest defaults are built in; a TOML file and command-line flags override them.
#pragma once

#include <stdexcept>
#include <string>

namespace dragon {

// Bad user input (a value out of range, a malformed file, an unknown flag).
// The CLI turns it into one line on stderr and exit code 2.
struct InputError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct BenchSpec {
    int bench_count = 223;       // benches in the chain; bench 1 is the head
    double head_length = 3.41;   // board length of bench 1, m
    double body_length = 2.20;   // board length of benches 2..N (body and tail), m
    double width = 0.30;         // board width, m
    double hole_offset = 0.275;  // hole centre to the nearer board end, m

    int handle_count() const { return bench_count + 1; }
    double board_length(int bench) const { return bench == 1 ? head_length : body_length; }
    // Handle-to-handle chord of bench 1..N.
    double link_length(int bench) const { return board_length(bench) - 2.0 * hole_offset; }
    // Chord from handle i to handle i+1 (i = 0..N-1): the link of bench i+1.
    double link_after(int handle) const { return link_length(handle + 1); }
    // Sum of the links, head handle to tail's rear handle, m.
    double chain_length() const { return link_length(1) + (bench_count - 1) * link_length(2); }
};

// How far along its path, as arc length from the spiral's centre, any handle may be, m. Points
// on a spiral are computed from the angle theta, whose rounding moves them by ~2 L eps at arc
// length L: 4e-9 m here, well below the 1e-6 m the tables print. (Ten thousand 2.2 m benches
// reach 2.2e4 m; a million, 2.2e6 m.)
inline constexpr double kMaxReach = 1e7;

enum class PathKind { spiral, turnaround };

struct PathSpec {
    PathKind kind = PathKind::spiral;
    double pitch = 0.55;        // coil-in pitch of the plain spiral (Q1-Q3), m
    double start_turn = 16.0;   // head starts at theta = 2 pi * start_turn on the plain spiral
    double turn_radius = 4.5;   // radius of the turning space, m
    double turn_pitch = 1.7;    // pitch of the spirals on the turnaround path (Q4, Q5), m
    double arc_ratio = 2.0;     // radius of the first S-curve arc over the second's
};

struct Scenario {
    BenchSpec bench;
    PathSpec path;
    double head_speed = 1.0;  // m/s along the path

    // The pitch of the spiral the head coils in along for this path kind.
    double coil_pitch() const { return path.kind == PathKind::spiral ? path.pitch : path.turn_pitch; }
};

// Throws InputError naming the first bad value and what is allowed.
void validate(const Scenario& s);

// Reads a TOML scenario over `base` (missing keys keep base's values); throws InputError
// for an unreadable or malformed file, an unknown key or a bad value.
Scenario load_scenario(const std::string& path, Scenario base = {});

const char* to_string(PathKind k);

// Is this the contest's own dragon, path and speed (the built-in defaults; the path kind aside)?
// Only then do remarks about the contest's paper apply to a scenario's answers.
bool is_contest_default(const Scenario& s);

}  // namespace dragon
