#include "cli/sweep_run.hpp"

#include <cstdio>
#include <filesystem>

#include <fmt/format.h>

#include "cli/progress.hpp"
#include "cli/status.hpp"
#include "cli/wording.hpp"
#include "dragon/atomic_file.hpp"

namespace dragon::cli {

namespace fs = std::filesystem;

std::string partial_path(const std::string& out) { return out + ".partial"; }

void check_output(const SweepOutput& o) {
    if (o.out.empty()) {
        if (o.resume) throw InputError("--resume is not allowed without -o: only a file's rows can be gone on with");
        return;
    }
    if (extension_of(o.out) != ".csv")
        throw InputError(fmt::format("-o {} has extension '{}': a sweep writes .csv", o.out, extension_of(o.out)));
    std::error_code ec;
    if (fs::exists(partial_path(o.out), ec) && !o.resume)
        throw InputError(fmt::format("-o {} is not allowed: {} holds the rows of an unfinished sweep; add --resume to "
                                     "go on with it, or remove it", o.out, partial_path(o.out)));
    AtomicFile probe(o.out);  // a folder in the way, or one that takes no files, fails now
}

namespace {

// The rows already written for this sweep (resuming): marks them done and hands each to on_row.
// Returns where its complete lines end.
std::size_t take_existing(const SweepSetup& setup, const std::string& path, const std::vector<std::string>& preamble,
                          std::vector<bool>& done, SweepTally& tally,
                          const std::function<void(const std::string&)>& on_row) {
    const std::size_t naxes = setup.grid.axes().size();
    std::size_t number = 0;
    const RowFileScan scan = scan_row_file(
        path, preamble.size(),
        [&](const std::vector<std::string>& found) {
            if (found != preamble)
                throw InputError(fmt::format("--resume is not allowed: '{}' holds the rows of another sweep (its "
                                             "first lines differ from this one's); run the same sweep, or remove it",
                                             path));
        },
        [&](const std::string& row) {
            ++number;
            const std::vector<std::string> fields = split_csv(row);
            const std::optional<std::size_t> index =
                fields.size() < naxes ? std::nullopt
                                      : setup.grid.index_of(std::vector<std::string>(fields.begin(), fields.begin() + static_cast<long>(naxes)));
            if (!index || !setup.shard.holds(*index))
                throw InputError(fmt::format("--resume is not allowed: row {} of '{}' is no scenario of this sweep's "
                                             "part: {:.80}", number, path, row));
            if (done[*index])
                throw InputError(fmt::format("--resume is not allowed: '{}' holds the scenario {} twice", path,
                                             csv_line(setup.grid.cells(*index))));
            done[*index] = true;
            ++tally.done_before;
            on_row(row);
        });
    return scan.complete_bytes;
}

}  // namespace

SweepTally run_rows(const SweepSetup& setup, const SweepOutput& o, const std::function<void(const std::string&)>& on_row) {
    const std::vector<std::string> preamble = {spec_line(setup), csv_line(header(setup))};
    SweepTally tally;
    tally.scenarios = setup.shard.size(setup.grid.size());
    std::vector<bool> done(setup.grid.size(), false);
    std::unique_ptr<RowLog> log;
    if (!o.out.empty()) {
        const std::string partial = partial_path(o.out);
        std::error_code ec;
        std::string source = o.out;  // where the rows gone on with were
        if (o.resume && fs::exists(partial, ec)) {
            source = partial;
            log = RowLog::reopen(partial, take_existing(setup, partial, preamble, done, tally, on_row));
        } else if (o.resume && fs::exists(o.out, ec)) {
            // A finished sweep: go on with a copy, so that it stays whole until the new one is.
            const std::size_t bytes = take_existing(setup, o.out, preamble, done, tally, on_row);
            fs::copy_file(o.out, partial, fs::copy_options::overwrite_existing);
            log = RowLog::reopen(partial, bytes);
        } else {
            log = RowLog::create(partial, preamble);
        }
        if (tally.done_before > 0)
            status(o.quiet, "resuming: {} of {} {} in {} already", tally.done_before,
                   count_of(static_cast<long long>(tally.scenarios), "row"), tally.done_before == 1 ? "is" : "are", source);
    } else if (!o.json) {
        for (const std::string& line : preamble) fmt::print("{}\n", line);
        std::fflush(stdout);
    }
    ProgressLine progress("scenarios", o.quiet);
    run_sweep<SweepRow>(
        setup.grid, setup.shard, done, default_executor(),
        [&](std::size_t index, int) { return make_row(setup, index); },
        [&](std::size_t, SweepRow&& row) {
            if (log) log->append(row.csv);
            else if (!o.json) fmt::print("{}\n", row.csv);
            if (o.json) print_json(row.json);
            if (!log || o.json) require_stdout_written();  // each row out as it finishes
            on_row(row.csv);
            ++tally.made;
            if (row.failed) ++tally.failed;
        },
        [&](std::int64_t made, std::int64_t total) { progress.update(made, total); });
    if (log) log->finish(o.out);
    return tally;
}

}  // namespace dragon::cli
