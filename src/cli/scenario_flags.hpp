// The scenario flags of the subcommands. Each command takes exactly the flags of the values it
// reads; precedence: flags over the --scenario file over the contest defaults.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "commands.hpp"
#include "dragon/atomic_file.hpp"
#include "dragon/scenario.hpp"

namespace dragon::cli {

// Which scenario values a command reads, on each path it can run on.
struct ScenarioUse {
    ScenarioValues on_spiral = 0;      // read on the plain spiral (0: the command never runs on it)
    ScenarioValues on_turnaround = 0;  // read on the turnaround path (0: never runs on it)
    bool path_choice = false;          // --path picks one of the two; else it runs on those above
    // Why the scenario flags it does not take are of no use to it, for the error message.
    const char* why_not = "";

    // simulate, collide: either path, chosen by --path (or the file's [path] kind).
    static ScenarioUse either_path();
    // render, video: either path; on the spiral the turning space is drawn (and video's --to
    // boundary is its edge), so the turn radius is read there too.
    static ScenarioUse drawing();
    // Q3: the plain spiral with the pitch searched, up to the turning space.
    static ScenarioUse pitch_search();
    // Q4, Q5: the turnaround path alone.
    static ScenarioUse turnaround_only();
    // solve, figures: both paths in one run.
    static ScenarioUse both_paths(const char* why_not);

    ScenarioValues all() const { return on_spiral | on_turnaround; }
};

class ScenarioFlags {
public:
    // Registers --scenario and the flags of the values `use` reads (and --path if it chooses).
    // (`reg` keeps the command's reason for the scenario flags it does not take.)
    void add_to(CLI::App* sub, ScenarioUse use, Registry& reg);
    // The scenario, validated for the values the command reads on its path (InputError names a
    // bad value, and the file when the value came from it). The file's old names are printed as
    // warnings on stderr, once. Refuses a flag the chosen path does
    // not read (--turn-pitch on the spiral, say). The path kind is the command's: the one
    // --path or the file picks, else its only path, else (both paths) the spiral. The --scenario
    // file is one of the inputs of `outputs`' run.
    Scenario resolve(RunOutputs* outputs) const;
    // The same for a run that reads only `reads` of the values (solve --only q4): values outside
    // it are not checked, and a flag for one is refused with "<flag> is not used: <why>".
    Scenario resolve(ScenarioValues reads, const std::string& why, RunOutputs* outputs) const;

    // The scenario flags given on the command line, one bit per value.
    ScenarioValues given() const;
    // Values from elsewhere (a sweep file) under the command line: `scenario_file` if --scenario
    // was not given, and each (key name, value: SweepFile::fixed) whose flag was not. Throws
    // InputError naming `source` for a name that is no scenario value or a value that is no number.
    void fill(const std::string& scenario_file, const std::vector<std::pair<std::string, std::string>>& values,
              const std::string& source);

    // For an option a subcommand does not take: if it is a scenario flag, one sentence saying
    // so and `why` (the command's reason, Registry::scenario_flags_unused); else "".
    static std::string not_taken(const CLI::App& sub, const std::string& flag, const std::string& why);

private:
    std::optional<double>* slot(ScenarioValues v);  // where a value's flag is stored
    const std::optional<double>* slot(ScenarioValues v) const { return const_cast<ScenarioFlags*>(this)->slot(v); }

    ScenarioUse use_;
    std::string file_;
    std::string path_kind_;
    std::optional<double> pitch_, speed_, head_length_, body_length_, width_, hole_offset_;
    std::optional<double> start_turn_, turn_radius_, turn_pitch_, arc_ratio_;
    std::optional<long long> bench_count_;
    // The scenario file's warnings (old names) are printed once, however often it is read.
    mutable bool warned_ = false;
};

}  // namespace dragon::cli
