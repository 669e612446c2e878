// What defines one sweep (its grid, measures, fixed scenario values, measure options and shard),
// built from the command line and a sweep file, written as the first line of its rows' file and
// read back from it (for --resume, merge and plots); and its rows.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "cli/report.hpp"
#include "cli/scenario_flags.hpp"
#include "dragon/sweep_measures.hpp"
#include "dragon/sweep.hpp"

namespace dragon::cli {

struct SweepSetup {
    SweepGrid grid;
    std::vector<const MeasureInfo*> measures;
    Scenario base;              // the fixed values (the contest's where none is given)
    ScenarioValues fixed = 0;   // the values some measure reads and no axis varies
    MeasureOptions options;
    Shard shard;
};

// What dragon sweep was asked, as text (the flags, then a sweep file under them).
struct SweepRequest {
    std::string file;                 // sweep file (TOML), or ""
    std::vector<std::string> vary;    // --vary, each NAME=VALUES
    std::vector<std::string> measures;
    std::optional<std::string> lo, hi;
    std::optional<double> grid, limit;
    std::optional<std::string> from, to;  // the window of collide, turnaround and max-speed
    std::string shard;                // "K/N", or "" for the whole sweep
};
// Throws InputError naming the flag or the file's key at fault: a bad --vary, an unknown or
// repeated measure, a measure that does not read a varied value, an option no measure takes, a
// fixed value that is also varied, a scenario flag no measure reads, a bad fixed value.
SweepSetup make_setup(const SweepRequest& request, ScenarioFlags& flags);

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
// measure's answer or null, the status).
struct SweepRow {
    std::string csv;
    Json json;
    bool failed = false;  // a measure failed for a reason other than the input's
};
SweepRow make_row(const SweepSetup& setup, std::size_t index);

}  // namespace dragon::cli
