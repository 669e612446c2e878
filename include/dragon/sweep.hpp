// Sweeps: the answers mapped over the design space. A sweep varies scenario values over ranges
// or lists (its axes), takes every combination of them (the grid, the first axis varying
// slowest), and streams one row per scenario into a file that is made durable row by row, so
// that a sweep killed at any moment goes on where it stopped. Shards split one sweep into
// disjoint parts for many machines.
//
// The library knows the grid, the shards, the rows' file (dragon/row_files.hpp, the io
// component) and how to run the scenarios on an executor; what a row holds (the analyses asked for, their answers' wording) is the caller's.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "dragon/executor.hpp"
#include "dragon/progress.hpp"
#include "dragon/scenario.hpp"

namespace dragon {

// A scenario value a sweep can vary, named as its command-line flag without the dashes.
struct SweepParameter {
    const char* name;      // "width", "body-length", ...
    ScenarioValues value;  // the value it sets
    bool whole;            // bench-count: whole numbers only
    const char* quantity;  // for a plot's axis: "bench width"
    const char* unit;      // "m", "m/s", or "" (a count, a ratio)
};
// Every parameter, in the order of the scenario flags.
const std::vector<SweepParameter>& sweep_parameters();
// The parameter of that name, or nullptr.
const SweepParameter* find_sweep_parameter(std::string_view name);
void set_parameter(Scenario& s, const SweepParameter& p, double v);  // s's value of p set to v
double get_parameter(const Scenario& s, const SweepParameter& p);     // s's value of p

// One varied value: its parameter and the values it takes, each with its cell, the text that
// identifies it in the rows (the shortest text that reads back as exactly that value).
struct Axis {
    const SweepParameter* parameter = nullptr;  // what it varies
    std::vector<double> values;                 // in its parameter's unit, in the order given
    std::vector<std::string> cells;             // each value's text in the rows, as `values`
};
// "width=0.20:0.40:21" (21 values from 0.20 to 0.40, both included, evenly spaced and rounded to
// 12 significant digits) or "speed=0.5,1,2" (a list; one value is a list too). Throws InputError
// naming the spec and what is allowed: an unknown name, a malformed or non-finite number, fewer
// than 1 or more than kMaxAxisValues values, a value twice, a bench count that is not whole.
Axis parse_axis(const std::string& spec);
// The axis from the cells a sweep file recorded; throws InputError as parse_axis does.
Axis axis_from_cells(const std::string& name, const std::vector<std::string>& cells);
inline constexpr std::size_t kMaxAxisValues = 100000;       // values on one axis
inline constexpr std::size_t kMaxSweepScenarios = 10000000;  // ten million rows: a few GB of CSV

// One of N disjoint parts of a sweep: scenario i belongs to shard K of N when i % N == K - 1, so
// the parts are the same size to within one and each spreads over the whole grid.
struct Shard {
    std::size_t index = 1;  // K, 1 <= K <= N
    std::size_t count = 1;  // N
    // Whether scenario `scenario` (0-based, of the whole grid) is in this shard.
    bool holds(std::size_t scenario) const { return scenario % count == index - 1; }
    // Scenarios of a grid of `total` in this shard.
    std::size_t size(std::size_t total) const { return total / count + (total % count > index - 1 ? 1 : 0); }
    // The j-th scenario of this shard.
    std::size_t scenario(std::size_t j) const { return j * count + (index - 1); }
};
// "K/N"; throws InputError naming the text.
Shard parse_shard(const std::string& text);

// Every combination of the axes' values.
class SweepGrid {
public:
    // Throws InputError for no axis, a parameter on two axes, or more than kMaxSweepScenarios.
    explicit SweepGrid(std::vector<Axis> axes);
    const std::vector<Axis>& axes() const { return axes_; }  // as given; the first varies slowest
    std::size_t size() const { return size_; }               // scenarios: the product of the axes' sizes
    // The position of scenario `index` on each axis.
    std::vector<std::size_t> position(std::size_t index) const;
    // `base` with the varied values of scenario `index`.
    Scenario scenario(Scenario base, std::size_t index) const;
    // The cells of scenario `index`, one per axis.
    std::vector<std::string> cells(std::size_t index) const;
    // The scenario whose cells are exactly these (one per axis), if any.
    std::optional<std::size_t> index_of(const std::vector<std::string>& cells) const;
    // The values the axes vary, one bit each.
    ScenarioValues varied() const;

private:
    std::vector<Axis> axes_;
    std::vector<std::unordered_map<std::string, std::size_t>> lookup_;  // each axis: cell -> position
    std::size_t size_ = 1;
};

// CSV (RFC 4180): a field quoted when it holds a comma, a quote or a line break.
std::string csv_field(std::string_view text);
std::string csv_line(const std::vector<std::string>& fields);  // joined by commas, no line end
// The fields of one line (without its line end); throws InputError for an unclosed quote.
std::vector<std::string> split_csv(std::string_view line);

// Runs the scenarios of `shard` not marked in `done` (indexed by scenario) on the executor: for
// each, make(index, worker) makes its row, then emit(index, row) takes it, one call at a time,
// in the order they finish; `progress` hears (rows made, rows to make) after each. Work the
// caller's make() does inside should run inline on its worker (its own parallel work would only
// queue behind the sweep's).
template <typename Row>
void run_sweep(const SweepGrid& grid, Shard shard, const std::vector<bool>& done, Executor& executor,
               const std::function<Row(std::size_t index, int worker)>& make,
               const std::function<void(std::size_t index, Row&& row)>& emit, const WorkProgress& progress = {}) {
    const std::size_t items = shard.size(grid.size());
    std::int64_t todo = 0;
    for (std::size_t j = 0; j < items; ++j) todo += done[shard.scenario(j)] ? 0 : 1;
    std::mutex emitting;
    std::int64_t made = 0;
    // Over the whole shard, skipping what is done: no list of scenarios is kept, so memory does
    // not grow with the sweep (a row is held only until it is emitted).
    executor.parallel_for(items, [&](std::size_t j, int worker) {
        const std::size_t index = shard.scenario(j);
        if (done[index]) return;
        Row row = make(index, worker);
        const std::lock_guard<std::mutex> hold(emitting);
        emit(index, std::move(row));
        ++made;
        if (progress) progress(made, todo);
    });
}

// What a sweep file says about the sweep (see assets/sweeps/): the command line's keys, a
// scenario value named as TOML names it (body_length), as in a scenario file. Values stay text,
// as on a command line; the caller parses them as it parses its flags.
struct SweepFile {
    std::vector<std::string> measures;  // measure = ["min-pitch", ...]: the measures' (commands') names
    // vary = ["width=0.20:0.40:21", "body_length=1.6:2.8:25"], the first axis first; held as
    // --vary takes them, the name with hyphens ("body-length=1.6:2.8:25").
    std::vector<std::string> vary;
    // scenario = "file.toml": as written (parse_sweep_file), relative to the sweep file's folder
    // once read_sweep_file has read it; "" if none.
    std::string scenario;
    // [fixed] name = value: the scenario value's key name (underscores), its value as text.
    std::vector<std::pair<std::string, std::string>> fixed;
    // [measure] key = value (a table per measure): ("min-pitch", "lo", "width+0.05").
    struct Option {
        std::string measure;  // "min-pitch"
        std::string key;      // "lo"
        std::string value;    // "width+0.05", as text
    };
    std::vector<Option> options;  // one per key given
    // One per old name read: a scenario value named as its flag is (body-length), in [fixed] or vary.
    KeyWarnings warnings;
};
// The sweep file's TOML `text`, `origin` naming it in messages (its path: a scenario it names
// is relative to it). Throws InputError naming the file and the key for malformed TOML, an
// unknown key or scenario value (listing the allowed names), or a value of the wrong type.
// Reads no file (read_sweep_file, dragon/input_files.hpp, the io component, reads one).
SweepFile parse_sweep_file(const std::string& text, const std::string& origin);

}  // namespace dragon
