// What dragon sweep can measure on each scenario: Q2's first contact, Q3's minimum pitch, Q4's
// turnaround (clearance and followability) and Q5's largest head speed, each answered exactly
// as its command's --json (cli/answers.hpp), then flattened into CSV cells.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "dragon/json.hpp"
#include "dragon/analyses.hpp"
#include "dragon/window.hpp"

namespace dragon {

struct MeasureOptions;

// One measure a sweep can take: its name, what it reads, how it answers and how its answer
// becomes a row's cells.
struct MeasureInfo {
    const char* name;        // as in --measure: "collide", "min-pitch", "turnaround", "max-speed"
    PathKind path;           // the path its command runs on
    ScenarioValues reads;    // the scenario values its command reads
    // The command's analysis and --json answer for a scenario of those values (checked), on the
    // calling thread; sets `jam` to a sentence where the end of the valid motion cut it short.
    Json (*answer)(const Scenario& s, const MeasureOptions& options, std::string& jam);
    // The answer's keys, flattened: a nested object's keys joined with dots ("jam.time"); arrays
    // and the values of the keys listed stay whole (a cell holds them as compact JSON).
    std::vector<std::string> columns;
    // What a plot shows: the key, its name and unit.
    const char* key;
    const char* quantity;
    const char* unit;
    // Whether a jam (the end of the valid motion cutting the analysis short) leaves `key` without
    // its full answer (collide: no contact before it; max-speed: a speed over part of the run).
    // min-pitch's jam is a pitch that cannot reach the boundary: its answer stands.
    bool jam_cuts_answer;
};
// Every measure, in the order above.
const std::vector<MeasureInfo>& sweep_measures();
// Throws InputError naming the measure and listing the others.
const MeasureInfo& find_measure(const std::string& name);

// A pitch bound of min-pitch's search: a number, the bench width plus one ("width+0.05"), for
// sweeps that vary the width, or "auto": each scenario's own default (default_pitch_range, as
// min-pitch and solve search it), the default.
struct PitchBound {
    double offset = 0.0;       // m: the pitch, or what is added to the bench width
    bool above_width = false;  // the bound is the bench width plus `offset`
    bool automatic = false;    // the bound is the scenario's default_pitch_range
    bool upper = false;        // which end of that range (the hi bound's)
    // The bound for this scenario; width+X rounded to 12 significant digits, as a sweep's values
    // are (0.42, not 0.42000000000000004: the same pitch the command's --lo 0.42 searches from).
    double at(const Scenario& s) const;
    std::string text() const;  // as given: "0.42", "width+0.05", "auto"
};
// The bound `text` gives (`upper`: the hi bound). Throws InputError naming `flag` and the text.
PitchBound parse_pitch_bound(const std::string& flag, const std::string& text, bool upper);

// The options of the measures (those of their commands a sweep passes on).
struct MeasureOptions {
    PitchBound lo{0.0, false, true, false};       // min-pitch --lo: each scenario's default
    PitchBound hi{0.0, false, true, true};        // min-pitch --hi: each scenario's default
    double grid = kDefaultPitchGrid;              // min-pitch --grid
    double limit = 2.0;                           // max-speed --limit
    // --from (and --to, below): the window of collide, turnaround and max-speed over their path's default
    // (default_window), as the commands take them.
    std::optional<Along> from;
    std::optional<Along> to;  // the window's end, as --to
    RunWindow window(PathKind kind) const;  // from and to over the default window on that path
    // The measures run on the calling thread (a sweep spreads its scenarios over the cores);
    // they stop when this executor asks (Executor::stop_requested), if given.
    const Executor* stop_source = nullptr;
};

// One measure on one scenario, on the calling thread.
struct MeasureResult {
    // collides: benches overlap where the analysis starts (a verdict, with no answer's cells).
    enum class State { ok, jam, collides, refused, failed };
    State state = State::ok;  // how the measure went
    std::optional<Json> answer;  // the command's --json (without its bulky tables); none when refused or failed
    std::string note;            // for the row's status: why it was refused or failed, where the jam is
};
// Checks the scenario for the measure and answers; never throws for the scenario's sake: a
// refusal (InputError), a collision at the start or a failure is the result's state and note.
MeasureResult run_measure(const MeasureInfo& m, const Scenario& s, const MeasureOptions& options);
// How a row's status begins the note of State::collides: "collides at the start (collide): ".
std::string overlap_note_prefix(const MeasureInfo& m);

// The cells of `answer` for `columns`: "" where a key is null or missing (a null object's keys
// too); text as it is; numbers, booleans, arrays and objects as compact JSON. Throws
// std::logic_error for a key of the answer that has no column (the list has fallen behind).
std::vector<std::string> flatten(const Json& answer, const std::vector<std::string>& columns);

}  // namespace dragon
