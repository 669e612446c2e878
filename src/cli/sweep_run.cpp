#include "sweep_run.hpp"

#include <sys/stat.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <set>

#include <fmt/format.h>

#include "progress.hpp"
#include "status.hpp"
#include "wording.hpp"
#include "sweep_row_check.hpp"
#include "dragon/atomic_file.hpp"
#include "dragon/input_file.hpp"

namespace dragon::cli {

namespace fs = std::filesystem;

std::string partial_path(const std::string& out) { return out + ".partial"; }

void check_output(const SweepOutput& o, RunOutputs* outputs) {
    if (o.out.empty()) {
        if (o.resume) throw InputError("--resume is not allowed without -o: only a file's rows can be gone on with");
        return;
    }
    if (extension_of(o.out) != ".csv")
        throw InputError(fmt::format("-o {} has extension '{}': a sweep writes .csv", o.out, extension_of(o.out)));
    std::error_code ec;
    const fs::file_status partial = fs::symlink_status(partial_path(o.out), ec);
    // A link there is none of the sweep's making: its rows would be read from, and the finished
    // file renamed from, wherever it points.
    if (fs::is_symlink(partial))
        throw InputError(fmt::format("-o {} is not allowed: {} is a symbolic link, and a sweep keeps its unfinished "
                                     "rows in a plain file of its own; remove the link", shown_text(o.out, 4096),
                                     shown_text(partial_path(o.out), 4096)));
    if (fs::exists(partial) && !o.resume)
        throw InputError(fmt::format("-o {} is not allowed: {} holds the rows of an unfinished sweep; add --resume to "
                                     "go on with it, or remove it", o.out, partial_path(o.out)));
    AtomicFile probe(o.out, outputs);  // a folder in the way, or one that takes no files, fails now
}

namespace {

RowFileLimits own_rows_limits(const SweepSetup& setup) {
    RowFileLimits limits = row_limits(setup, "sweep rows");
    limits.output_too = true;  // this sweep's own rows, gone on with: -o may well be the file
    return limits;
}

// The rows already written for this sweep (resuming): marks them done and hands each to
// on_row. A row whose measure failed (for a reason not the scenario's) is not taken: it is
// computed again. Returns where the file's complete lines end, and the failed rows' lines.
struct Existing {
    std::size_t complete_bytes = 0;
    std::set<std::size_t> failed_lines;
};
Existing take_existing(const SweepSetup& setup, const std::string& path, const std::vector<std::string>& preamble,
                       std::vector<bool>& done, SweepTally& tally, const std::function<void(const std::string&)>& on_row) {
    std::size_t number = preamble.size();  // the line being read
    Existing out;
    const RowFileScan scan = scan_row_file(
        path, preamble.size(),
        [&](const std::vector<std::string>& found) {
            const std::string why = found[0] != preamble[0] ? spec_difference(found[0], preamble[0])
                                    : found[1] != preamble[1] ? "its header (line 2) differs from this sweep's"
                                                              : "";
            if (!why.empty())
                throw InputError(fmt::format("--resume is not allowed: '{}' holds the rows of another sweep: {}; run "
                                             "the same sweep, or remove it", shown_text(path, 4096), why));
        },
        [&](const std::string& row) {
            ++number;
            const RowCheck check = check_row(setup, row);
            if (!check.index)
                throw InputError(fmt::format("--resume is not allowed: line {} of '{}' is not a row of this sweep: {}: "
                                             "{}", number, shown_text(path, 4096), check.problem, shown_text(row, 60)));
            if (done[*check.index])
                throw InputError(fmt::format("--resume is not allowed: '{}' holds the scenario {} twice (line {})",
                                             shown_text(path, 4096), csv_line(setup.grid.cells(*check.index)), number));
            if (check.failed) {
                out.failed_lines.insert(number);
                return;
            }
            done[*check.index] = true;
            ++tally.done_before;
            on_row(row);
        },
        own_rows_limits(setup));
    out.complete_bytes = scan.complete_bytes;
    return out;
}

// `partial` made anew from `source`'s complete lines but `dropped` (their row is computed
// again), durably, replacing it whole; returns its size.
std::size_t rewrite_without(const SweepSetup& setup, const std::string& source, const std::string& partial,
                            const std::set<std::size_t>& dropped) {
    const fs::path p(partial);
    const std::string temp = (p.parent_path() / ("." + p.filename().string() + ".rewrite")).string();
    std::string text;
    std::size_t number = 2;  // the line being read
    scan_row_file(
        source, 2,
        [&](const std::vector<std::string>& preamble) {
            for (const std::string& line : preamble) text += line + "\n";
        },
        [&](const std::string& line) {
            if (!dropped.count(++number)) text += line + "\n";
        },
        own_rows_limits(setup));
    {
        fs::remove(temp);
        struct stat was {};
        std::unique_ptr<RowLog> log =
            RowLog::create(temp, {}, ::stat(source.c_str(), &was) == 0 ? was.st_mode & 0777 : 0666);
        log->append(text.substr(0, text.empty() ? 0 : text.size() - 1));
    }
    std::error_code ec;
    fs::rename(temp, partial, ec);
    if (ec) throw FileError(partial, "write", ec.message());
    return text.size();
}

}  // namespace

SweepTally run_rows(const SweepSetup& setup, const SweepOutput& o, Executor& executor,
                    const std::function<void(const std::string&)>& on_row, RunOutputs* outputs) {
    const std::vector<std::string> preamble = {spec_line(setup), csv_line(header(setup))};
    SweepTally tally;
    tally.scenarios = setup.shard.size(setup.grid.size());
    std::vector<bool> done(setup.grid.size(), false);
    std::unique_ptr<RowLog> log;
    if (!o.out.empty()) {
        const std::string partial = partial_path(o.out);
        std::error_code ec;
        std::string source = o.out;  // where the rows gone on with were
        if (o.resume && (fs::exists(fs::symlink_status(partial, ec)) || fs::exists(o.out, ec))) {
            // Going on with the unfinished rows, or with a finished sweep through a copy of it, so
            // that it stays whole until the new one is.
            const bool unfinished = fs::exists(fs::symlink_status(partial, ec));
            source = unfinished ? partial : o.out;
            const Existing existing = take_existing(setup, source, preamble, done, tally, on_row);
            std::size_t bytes = existing.complete_bytes;
            if (!existing.failed_lines.empty()) {
                bytes = rewrite_without(setup, source, partial, existing.failed_lines);
                status(o.quiet, "resuming: {} failed row{} of {} made again", existing.failed_lines.size(),
                       existing.failed_lines.size() == 1 ? "" : "s", source);
            } else if (!unfinished) {
                fs::copy_file(o.out, partial, fs::copy_options::overwrite_existing);
            }
            log = RowLog::reopen(partial, bytes);
        } else {
            // No more readable than the file it will replace (a 0600 OUT.csv: 0600 rows).
            struct stat old {};
            log = RowLog::create(partial, preamble, ::stat(o.out.c_str(), &old) == 0 ? old.st_mode & 0777 : 0666);
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
        setup.grid, setup.shard, done, executor,
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
    if (log) log->finish(o.out, outputs);
    return tally;
}

}  // namespace dragon::cli
