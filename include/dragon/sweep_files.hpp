// A sweep's rows files: written row by row and made durable as they finish, gone on with after a
// kill (resume), and a sweep's parts (its shards) merged into one file. Every front end (the
// tool's `dragon sweep`, Python's sweep()) writes, resumes and merges through these, so a file
// begun by one is finished by another, byte for byte as either would have written it.
//
// The library prints nothing: what a person may want to hear ("resuming: ...") goes to a
// callback, and refusals are InputErrors naming the value at fault by its Key (Key::out, the
// rows' file; Key::resume, going on with it) or, for a part of a merge, the file and the line.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "dragon/executor.hpp"
#include "dragon/progress.hpp"
#include "dragon/row_files.hpp"
#include "dragon/sweep.hpp"
#include "dragon/sweep_setup.hpp"

namespace dragon {

class RunOutputs;  // dragon/atomic_file.hpp (the io component)

// Where the rows of an unfinished sweep into `out` are kept: "<out>.partial".
std::string partial_path(const std::string& out);

// Where a sweep's rows go.
struct SweepOutputRequest {
    std::string out;      // a .csv file; "" for none (the rows go only to the caller's callbacks)
    bool resume = false;  // go on with <out>.partial (or a finished <out>) instead of starting afresh
    RunOutputs* outputs = nullptr;  // the run `out` is one of the outputs of (null: placed at once)
};

// Checks the output before any work: `out` is a .csv whose folder takes files; resuming needs an
// `out`; an unfinished sweep's rows (<out>.partial) are not overwritten without resuming, and
// are a plain file, not a link. Throws InputError: Key::out with the path, or Key::resume with
// "true" (resume asked, and refused) or "false" (not asked, and needed: `allowed` says which
// file holds the unfinished rows).
void check_sweep_output(const SweepOutputRequest& request);

// What the caller hears while a sweep's file is written.
using SweepRowHeard = std::function<void(std::size_t scenario, const std::string& csv_row)>;
using SweepNoteHeard = std::function<void(const std::string& note)>;

// A sweep's rows file, open for appending: made anew, or resumed. Resuming reads the rows already
// written (in <out>.partial, or in a finished <out> through a copy, so that it stays whole until
// the new one is): each is checked (check_row) and handed to `on_resumed`; a torn last line (a
// kill while it was written) is cut off; a row whose measure failed for a reason not the
// scenario's is dropped, to be made again. Rows are appended from any thread, each made durable
// before append() returns, and finish() renames the file to `out`.
class SweepWriter {
public:
    // Checks the request (check_sweep_output) and opens the file. `on_note` hears what resuming
    // found ("resuming: 12 of 30 rows are in rows.csv.partial already"). Throws InputError
    // (Key::resume) for a file that holds another sweep's rows, a line that is no row of this
    // sweep, or a scenario twice, naming the file and the line.
    SweepWriter(const SweepSetup& setup, const SweepOutputRequest& request, const SweepRowHeard& on_resumed = {},
                const SweepNoteHeard& on_note = {});
    ~SweepWriter();
    SweepWriter(const SweepWriter&) = delete;
    SweepWriter& operator=(const SweepWriter&) = delete;

    // Which scenarios of the grid (indexed as the grid) the file holds already.
    const std::vector<bool>& done() const { return done_; }
    std::size_t done_before() const { return done_before_; }  // how many
    // Where the resumed rows were read: <out>.partial, or <out> for a finished sweep.
    const std::string& resumed_from() const { return source_; }
    // Appends one row (a line make_row wrote for this sweep) and makes it durable; throws
    // std::runtime_error naming the file when the write fails.
    void append(const std::string& csv_row);
    // Renames the rows to `out`, the sweep finished (see RowLog::finish).
    void finish();

private:
    std::string out_, source_;
    RunOutputs* outputs_ = nullptr;
    std::vector<bool> done_;
    std::size_t done_before_ = 0;
    std::unique_ptr<RowLog> log_;
};

// What one run of a sweep did.
struct SweepTally {
    std::size_t scenarios = 0;    // in this shard
    std::size_t done_before = 0;  // rows found already written (resuming)
    std::size_t made = 0;         // rows made by this run
    std::size_t failed = 0;       // of those, rows where a measure failed for a reason not the input's
};

// What write_sweep's caller hears; any may be empty.
struct SweepCallbacks {
    SweepRowHeard on_row;                               // every row: the resumed ones first, then each made
    std::function<void(const SweepRow& row)> on_made;  // each row this run made, once it is written
    SweepNoteHeard on_note;                             // what resuming found
    WorkProgress progress;                              // (rows made, rows to make)
};

// Runs the rows of the setup's shard not yet written on `executor`, each scenario's measures on
// one worker, into `request.out` (a SweepWriter) or, without one, only to the callbacks. Rows
// finish in any order and each is written as soon as it does. The file is finished (renamed to
// `out`) only when no row failed: a sweep with failed rows keeps them in <out>.partial, and
// resuming makes them again.
SweepTally write_sweep(const SweepSetup& setup, const SweepOutputRequest& request, Executor& executor,
                       const SweepCallbacks& callbacks = {});

// The whole sweep the files are parts of, from the first one's first line (its shard 1/1).
// Throws InputError for no part, or a first line that describes no sweep.
// The first part is one of the inputs of `outputs`' run.
SweepSetup whole_sweep(const std::vector<std::string>& parts, RunOutputs* outputs = nullptr);

// Writes the parts' rows, in the files' order, to `out` (a .csv) all-or-nothing. Throws
// InputError: Key::out for an `out` that is not a .csv; else naming the file and the line at
// fault: a file of another sweep (its first line or header differs), a part that is `out`
// itself, a torn last line (an unfinished part: resume it first), a row that is no scenario of
// the sweep, a scenario twice (with the files it is in), or scenarios missing (how many, and
// the first). `on_row` hears every row. Returns the number of rows. The parts are inputs of
// `outputs`' run, and `out` one of its outputs.
std::size_t merge_sweep_parts(const SweepSetup& whole, const std::string& out, const std::vector<std::string>& parts,
                              const SweepRowHeard& on_row = {}, RunOutputs* outputs = nullptr);

}  // namespace dragon
