// A scenario: the dragon's benches, the path it follows and how fast its head moves.
// Contest defaults are built in; a TOML file and command-line flags override them.
#pragma once

#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

#include "dragon/errors.hpp"

namespace dragon {

// The most benches a chain may have.
inline constexpr int kMaxBenchCount = 1000000;

// The benches: how many, and each board's size and where its holes are.
struct BenchSpec {
    int bench_count = 223;       // benches in the chain; bench 1 is the head
    double head_length = 3.41;   // board length of bench 1, m
    double body_length = 2.20;   // board length of benches 2..N (body and tail), m
    double width = 0.30;         // board width, m
    double hole_offset = 0.275;  // hole centre to the nearer board end, m

    int handle_count() const { return bench_count + 1; }  // N + 1: a handle at each end of every bench
    // Board length of bench 1..N, m.
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

// The path the head follows: the plain spiral, coiling in (Q1-Q3), or the turnaround path:
// the coil-in spiral, the S-curve in the turning space and the coil-out spiral (Q4, Q5).
enum class PathKind { spiral, turnaround };

// The path's kind and its shape's values (each kind reads its own).
struct PathSpec {
    PathKind kind = PathKind::spiral;  // which path
    double pitch = 0.55;        // coil-in pitch of the plain spiral (Q1-Q3), m
    double start_turn = 16.0;   // head starts at theta = 2 pi * start_turn on the plain spiral
    double turn_radius = 4.5;   // radius of the turning space, m
    double turn_pitch = 1.7;    // pitch of the spirals on the turnaround path (Q4, Q5), m
    double arc_ratio = 2.0;     // radius of the first S-curve arc over the second's
};

// Everything a Simulation needs: the benches, the path and the head's speed.
struct Scenario {
    BenchSpec bench;  // the benches
    PathSpec path;    // the path
    double head_speed = 1.0;  // m/s along the path

    // The pitch of the spiral the head coils in along for this path kind.
    double coil_pitch() const { return path.kind == PathKind::spiral ? path.pitch : path.turn_pitch; }
};

// The values of a scenario, one bit each, so that a check covers only what a computation reads:
// a turnaround study never reads the plain spiral's pitch, so a file's pitch of 0.1 m is no
// reason to refuse it.
using ScenarioValues = unsigned;
namespace value {
inline constexpr ScenarioValues bench_count = 1u << 0;  // BenchSpec::bench_count
inline constexpr ScenarioValues head_length = 1u << 1;  // BenchSpec::head_length
inline constexpr ScenarioValues body_length = 1u << 2;  // BenchSpec::body_length
inline constexpr ScenarioValues width = 1u << 3;        // BenchSpec::width
inline constexpr ScenarioValues hole_offset = 1u << 4;  // BenchSpec::hole_offset
inline constexpr ScenarioValues head_speed = 1u << 5;   // Scenario::head_speed
inline constexpr ScenarioValues pitch = 1u << 6;        // the plain spiral's
inline constexpr ScenarioValues start_turn = 1u << 7;   // the plain spiral's
inline constexpr ScenarioValues turn_radius = 1u << 8;  // the turning space
inline constexpr ScenarioValues turn_pitch = 1u << 9;   // the turnaround path's spirals
inline constexpr ScenarioValues arc_ratio = 1u << 10;   // the turnaround path's S-curve
inline constexpr ScenarioValues bench = bench_count | head_length | body_length | width | hole_offset;  // the benches' values
inline constexpr ScenarioValues all = (1u << 11) - 1;  // every value above
}  // namespace value

// What a Simulation on a path of this kind reads: the benches and the head speed, and the
// plain spiral's pitch and start turn or the turnaround path's turn radius, pitch and ratio.
ScenarioValues values_read(PathKind kind);

// A value that is not allowed (its key, as given, and what is allowed), and which values the
// failed rule involves (one, or two or more for a rule between them, such as the pitch against
// the width; the key is the one the sentence is about).
struct ScenarioError : InputError {
    // `what`: the whole sentence; `involved`: the values of the rule it breaks.
    ScenarioError(Key key, std::string value, std::string allowed, const std::string& what, ScenarioValues involved)
        : InputError(key, std::move(value), std::move(allowed), what), values(involved) {}
    ScenarioValues values;  // the values the failed rule involves
};

// Throws the ScenarioError of a bench count outside 1..kMaxBenchCount, `given` as written (a
// front end checks a whole number before it narrows it to an int).
[[noreturn]] void refuse_bench_count(const std::string& given);

// Throws ScenarioError naming the first bad value among `values` and what is allowed. A rule
// between values is checked when all of them are among `values`.
void validate(const Scenario& s, ScenarioValues values);
// validate(s, values_read(s.path.kind)): what a Simulation of s needs.
void validate(const Scenario& s);

// A scenario file: flat keys named as the key table names them (dragon/keys.hpp), one rule for
// every front end: the flag's name with underscores.
//     pitch = 0.55        # --pitch
//     speed = 1.0         # --speed
//     bench_count = 223   # --bench-count
//     path = "spiral"     # --path
// The old form, sections [dragon], [path] and [motion] with [path] kind and [motion] head_speed,
// is read too, each old name with one KeyWarning naming its key today.

// A scenario read from a TOML file, which values the file set, and a warning for each old name.
struct LoadedScenario {
    Scenario scenario;          // the file's values over the base
    ScenarioValues values = 0;  // the values the file set
    KeyWarnings warnings;       // one per old name the file used, section by section
};

// An old name a scenario file may still use: "[section] name", and the key it sets today.
struct OldScenarioName {
    std::string_view section;  // "dragon", "path" or "motion"
    std::string_view name;     // "head_speed"
    Key key;                   // Key::speed
};
// Every old name, section by section.
std::span<const OldScenarioName> old_scenario_names();
// Whether a scenario file holds this key: every key that sets a scenario value, and the path.
bool in_scenario_file(Key k);

// A scenario from a TOML file's text over `base` (missing keys keep base's values); `origin`
// names the file in messages. Throws InputError for malformed TOML, an unknown section or key
// (listing the allowed ones), a value of the wrong type (with its Key), or one key given in both
// forms (naming both). Values are not range-checked here: validate() does that for those a
// computation reads. Reads no file (read_scenario_file and load_scenario, dragon/input_files.hpp,
// the io component, read one).
LoadedScenario parse_scenario_toml(const std::string& text, const std::string& origin, Scenario base = {});

// The scenario as a file in today's form, every value written (a key per line, path first): what
// parse_scenario_toml reads back to `s`, digit for digit.
std::string scenario_toml(const Scenario& s);

// "spiral" or "turnaround".
const char* to_string(PathKind k);

// Is this the contest's own dragon, path and speed (the built-in defaults; the path kind aside)?
// Only then do remarks about the contest's paper apply to a scenario's answers.
bool is_contest_default(const Scenario& s);

}  // namespace dragon
