// A sweep's rows written to their file and gone on with after a kill (dragon/sweep_files.hpp).
#include <sys/stat.h>

#include <filesystem>
#include <memory>
#include <set>

#include <fmt/format.h>

#include "dragon/atomic_file.hpp"
#include "dragon/input_file.hpp"
#include "dragon/sweep_files.hpp"
#include "dragon/sweep_row_check.hpp"

namespace dragon {

namespace fs = std::filesystem;

std::string partial_path(const std::string& out) { return out + ".partial"; }

void check_sweep_output(const SweepOutputRequest& r) {
    if (r.out.empty()) {
        if (r.resume)
            throw InputError(Key::resume, "true", "only an output file's rows can be gone on with, and none is given");
        return;
    }
    if (extension_of(r.out) != ".csv")
        throw InputError(Key::out, r.out, fmt::format("a sweep writes .csv (it has extension '{}')", extension_of(r.out)));
    std::error_code ec;
    const fs::file_status partial = fs::symlink_status(partial_path(r.out), ec);
    // A link there is none of the sweep's making: its rows would be read from, and the finished
    // file renamed from, wherever it points.
    if (fs::is_symlink(partial))
        throw InputError(Key::out, shown_text(r.out, 4096),
                         fmt::format("{} is a symbolic link, and a sweep keeps its unfinished rows in a plain file of "
                                     "its own; remove the link", shown_text(partial_path(r.out), 4096)));
    // Resuming is what is missing: the front end names its own way of asking for it.
    if (fs::exists(partial) && !r.resume)
        throw InputError(Key::resume, "false",
                         fmt::format("{} holds the rows of an unfinished sweep", shown_text(partial_path(r.out), 4096)),
                         fmt::format("output file {} is not allowed without resuming: {} holds the rows of an "
                                     "unfinished sweep; go on with it, or remove it", shown_text(r.out, 4096),
                                     shown_text(partial_path(r.out), 4096)));
    AtomicFile probe(r.out, r.outputs);  // a folder in the way, or one that takes no files, fails now
}

namespace {

// A refusal of the rows a resumed file holds: resuming is what cannot be done.
InputError cannot_resume(const std::string& why) {
    return InputError(Key::resume, "true", why, fmt::format("resume is not allowed: {}", why));
}

RowFileLimits own_rows_limits(const SweepSetup& setup) {
    RowFileLimits limits = row_limits(setup, "sweep rows");
    limits.output_too = true;  // this sweep's own rows, gone on with: the output may well be the file
    return limits;
}

// The rows already written for this sweep: marks them done and hands each to on_row. A row
// whose measure failed (for a reason not the scenario's) is not taken: it is computed again.
// Returns where the file's complete lines end, and the failed rows' line numbers.
struct Existing {
    std::size_t complete_bytes = 0;
    std::set<std::size_t> failed_lines;
};
Existing take_existing(const SweepSetup& setup, const std::string& path, const std::vector<std::string>& preamble,
                       std::vector<bool>& done, std::size_t& taken, const SweepRowHeard& on_row) {
    std::size_t number = preamble.size();  // the line being read
    Existing out;
    const RowFileScan scan = scan_row_file(
        path, preamble.size(),
        [&](const std::vector<std::string>& found) {
            const std::string why = found[0] != preamble[0] ? spec_difference(found[0], preamble[0])
                                    : found[1] != preamble[1] ? "its header (line 2) differs from this sweep's"
                                                              : "";
            if (!why.empty())
                throw cannot_resume(fmt::format("'{}' holds the rows of another sweep: {}; run the same sweep, or "
                                                "remove it", shown_text(path, 4096), why));
        },
        [&](const std::string& row) {
            ++number;
            const RowCheck check = check_row(setup, row);
            if (!check.index)
                throw cannot_resume(fmt::format("line {} of '{}' is not a row of this sweep: {}: {}", number,
                                                shown_text(path, 4096), check.problem, shown_text(row, 60)));
            if (done[*check.index])
                throw cannot_resume(fmt::format("'{}' holds the scenario {} twice (line {})", shown_text(path, 4096),
                                                csv_line(setup.grid.cells(*check.index)), number));
            if (check.failed) {
                out.failed_lines.insert(number);
                return;
            }
            done[*check.index] = true;
            ++taken;
            if (on_row) on_row(*check.index, row);
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
    // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "." + a string here.
    std::string name = ".";
    name += p.filename().string();
    name += ".rewrite";
    const std::string temp = (p.parent_path() / name).string();
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

std::string rows_of(std::size_t n) { return fmt::format("{} row{}", n, n == 1 ? "" : "s"); }

}  // namespace

SweepWriter::SweepWriter(const SweepSetup& setup, const SweepOutputRequest& request, const SweepRowHeard& on_resumed,
                         const SweepNoteHeard& on_note)
    : out_(request.out), source_(request.out), outputs_(request.outputs), done_(setup.grid.size(), false) {
    check_sweep_output(request);
    if (out_.empty()) throw InputError(Key::out, "", "give the .csv file the rows go to");
    const std::vector<std::string> preamble = {spec_line(setup), csv_line(header(setup))};
    const std::string partial = partial_path(out_);
    std::error_code ec;
    const bool unfinished = fs::exists(fs::symlink_status(partial, ec));
    if (request.resume && (unfinished || fs::exists(out_, ec))) {
        // Going on with the unfinished rows, or with a finished sweep through a copy of it, so
        // that it stays whole until the new one is.
        source_ = unfinished ? partial : out_;
        const Existing existing = take_existing(setup, source_, preamble, done_, done_before_, on_resumed);
        std::size_t bytes = existing.complete_bytes;
        if (!existing.failed_lines.empty()) {
            bytes = rewrite_without(setup, source_, partial, existing.failed_lines);
            if (on_note)
                on_note(fmt::format("resuming: {} failed {} of {} made again", existing.failed_lines.size(),
                                    existing.failed_lines.size() == 1 ? "row" : "rows", source_));
        } else if (!unfinished) {
            fs::copy_file(out_, partial, fs::copy_options::overwrite_existing);
        }
        log_ = RowLog::reopen(partial, bytes);
    } else {
        // No more readable than the file it will replace (a 0600 OUT.csv: 0600 rows).
        struct stat old {};
        log_ = RowLog::create(partial, preamble, ::stat(out_.c_str(), &old) == 0 ? old.st_mode & 0777 : 0666);
    }
    if (done_before_ > 0 && on_note)
        on_note(fmt::format("resuming: {} of {} {} in {} already", done_before_,
                            rows_of(setup.shard.size(setup.grid.size())), done_before_ == 1 ? "is" : "are", source_));
}

SweepWriter::~SweepWriter() = default;

void SweepWriter::append(const std::string& csv_row) { log_->append(csv_row); }

void SweepWriter::finish() { log_->finish(out_, outputs_); }

SweepTally write_sweep(const SweepSetup& setup, const SweepOutputRequest& request, Executor& executor,
                       const SweepCallbacks& cb) {
    SweepTally tally;
    tally.scenarios = setup.shard.size(setup.grid.size());
    std::unique_ptr<SweepWriter> file;
    if (request.out.empty()) check_sweep_output(request);
    else file = std::make_unique<SweepWriter>(setup, request, cb.on_row, cb.on_note);
    const std::vector<bool> none(file ? 0 : setup.grid.size(), false);
    tally.done_before = file ? file->done_before() : 0;
    run_sweep<SweepRow>(
        setup.grid, setup.shard, file ? file->done() : none, executor,
        [&](std::size_t index, int) { return make_row(setup, index); },
        [&](std::size_t index, SweepRow&& row) {
            if (file) file->append(row.csv);
            if (cb.on_made) cb.on_made(row);
            if (cb.on_row) cb.on_row(index, row.csv);
            ++tally.made;
            if (row.failed) ++tally.failed;
        },
        cb.progress);
    // A failed row stays unfinished: the rows stay in the partial file, where resuming finds it.
    if (file && tally.failed == 0) file->finish();
    return tally;
}

}  // namespace dragon
