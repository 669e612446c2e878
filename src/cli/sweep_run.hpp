// Running a sweep's rows: into a file made durable row by row (resumable after a kill), or onto
// stdout; rows finish in any order, each written as soon as it does.
#pragma once

#include <functional>
#include <string>

#include "sweep_setup.hpp"
#include "dragon/executor.hpp"

namespace dragon::cli {

struct SweepOutput {
    std::string out;      // -o FILE.csv; "" for stdout
    bool resume = false;  // go on with FILE.csv.partial (or FILE.csv) instead of starting afresh
    bool json = false;    // each row as a JSON object on stdout, one a line
    bool quiet = false;
};

struct SweepTally {
    std::size_t scenarios = 0;    // in this shard
    std::size_t done_before = 0;  // rows found already written (--resume)
    std::size_t made = 0;         // rows made by this run
    std::size_t failed = 0;       // of those, rows where a measure failed for a reason not the input's
};

// Where the rows of an unfinished sweep into `out` are kept: "<out>.partial".
std::string partial_path(const std::string& out);

// Checks the output before any work: -o is a .csv whose folder takes files; --resume has an -o;
// and an unfinished sweep's rows are not overwritten without --resume. Throws InputError.
void check_output(const SweepOutput& output, RunOutputs* outputs);

// Runs the rows of the setup's shard not yet written on `executor`, each scenario's measures on
// one worker. The rows go to <out>.partial as they finish, which is renamed to <out> when all
// are there (one of `outputs`' files); `on_row` hears every row's CSV line, the resumed ones first.
SweepTally run_rows(const SweepSetup& setup, const SweepOutput& output, Executor& executor,
                    const std::function<void(const std::string& csv_row)>& on_row, RunOutputs* outputs);

}  // namespace dragon::cli
