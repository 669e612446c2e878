// What defines one sweep (its grid, measures, fixed scenario values, measure options and shard),
// written as the first line of its rows' file and read back from it (for --resume, merge and
// plots), and its rows: the tool's `dragon sweep` and Python's sweep() make the same rows.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "dragon/json.hpp"
#include "dragon/sweep.hpp"
#include "dragon/sweep_measures.hpp"

namespace dragon {

// One sweep, checked: every scenario it runs and every measure it takes on each.
struct SweepSetup {
    SweepGrid grid;                            // the varied values: one scenario per point
    std::vector<const MeasureInfo*> measures;  // each once, in the order asked
    Scenario base;              // the fixed values (the contest's where none is given)
    ScenarioValues fixed = 0;   // the values some measure reads and no axis varies
    MeasureOptions options;     // the measures' options, checked
    Shard shard;                // the part of the grid this run makes
};

// What a sweep was asked, as its caller gives it (the tool's flags and sweep file, Python's
// keyword arguments), to be checked and made into a setup.
struct SweepAsked {
    std::vector<std::string> vary;      // each NAME=FROM:TO:COUNT or NAME=V1,V2,... (parse_axis)
    std::vector<std::string> measures;  // collide, min-pitch, turnaround, max-speed
    std::optional<std::string> lo;      // min-pitch's lower bound: a pitch (m), or "width+X"
    std::optional<std::string> hi;      // min-pitch's upper bound, the same way
    std::optional<double> grid;         // min-pitch's grid step, m
    std::optional<double> limit;        // max-speed's limit on any handle's speed, m/s
    std::optional<std::string> from;    // where the window of collide, turnaround and max-speed starts (parse_along)
    std::optional<std::string> to;      // and where it ends
    std::string shard;                    // "K/N", or "" for the whole sweep
    ScenarioValues fixed_given = 0;       // scenario values the caller fixed (none may be varied too)
};
// How the caller names what it was given, for messages: an option ("lo" -> "--lo") and a scenario
// value ("width" -> "--width").
struct SweepWords {
    std::function<std::string(const char* option)> option;  // "lo" -> "--lo"
    std::function<std::string(const char* value)> value;    // "width" -> "--width"
};
// Checks what was asked and makes the setup. `base(fixed, why)` gives the scenario of the fixed
// values: the values some measure reads and no axis varies (a value given that none reads is
// refused there, with `why`). Throws InputError naming what is at fault in the caller's words:
// no axis or measure, a bad axis, a measure given twice or not reading a varied value, an option
// no measure takes or that every scenario would refuse, a value both fixed and varied.
SweepSetup make_sweep_setup(const SweepAsked& asked, const SweepWords& words,
                            const std::function<Scenario(ScenarioValues fixed, const std::string& why)>& base);

// Is `name` ("min-pitch") among the measures?
bool has_measure(const std::vector<const MeasureInfo*>& measures, const char* name);
// "collide, max-speed": the measures' names.
std::string measure_names(const std::vector<const MeasureInfo*>& measures);
// What min-pitch and max-speed refuse in an option whatever the scenario (the rules of
// min_pitch() and max_head_speed()): a sweep refuses it once, up front, rather than writing
// "refused" into every row. What depends on the scenario (a bound below its width) stays a
// row's refusal. nullopt when the option is fine.
std::optional<std::string> limit_problem(double limit);
std::optional<std::string> grid_problem(double grid);
// Throws InputError for an option of the measures that every scenario would refuse, naming it
// by `name("limit")` (the caller's name for it: a flag, a file's key, a keyword argument).
void check_options(const MeasureOptions& o, const std::vector<const MeasureInfo*>& measures,
                   const std::function<std::string(const char* option)>& name);

// The first line of a rows' file: "# dragon sweep " and the setup as one JSON object.
std::string spec_line(const SweepSetup& setup);
// The setup a spec line describes; throws InputError naming `file` if it is not one.
SweepSetup read_spec_line(const std::string& line, const std::string& file);
// What makes a file's first line `found` differ from this sweep's `expected`, in words ("it
// varies width over [...], and this sweep over [...]"), for refusing its rows.
std::string spec_difference(const std::string& found, const std::string& expected);
// The same line without its shard: the sweep the shards are parts of.
std::string whole_spec_line(const std::string& line, const std::string& file);

// The second line: the varied values' names, each measure's columns prefixed by its name
// ("min-pitch.pitch"), then "status".
std::vector<std::string> header(const SweepSetup& setup);

// One scenario's row: its CSV line and the same as a JSON object (the varied values, each
// measure's answer or null, the status). Its measures run on the calling thread.
struct SweepRow {
    std::string csv;      // one line, no newline, in header()'s columns
    Json json;            // the same values as an object
    bool failed = false;  // a measure failed for a reason other than the input's
};
// Runs the measures on scenario `index` of the setup's grid (0 .. grid size - 1); a scenario the
// measures refuse is a row saying so, not an error.
SweepRow make_row(const SweepSetup& setup, std::size_t index);

}  // namespace dragon
