// A sweep's rows on disk (the io component): reading a rows' file back, a line at a time and
// dropping a torn last line, and the durable append-only log rows are written to as they
// finish. What the rows mean (the grid, the shards, their CSV) is the core's: dragon/sweep.hpp.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace dragon {

class RunOutputs;  // dragon/atomic_file.hpp

// A rows' file read through: its first lines (the preamble: what the sweep is and the header),
// and how many rows, each a complete line, follow. A last line without its line end (a kill
// while it was written) is not a row: `torn` says there was one, `complete_bytes` where it began.
struct RowFileScan {
    std::vector<std::string> preamble;  // its first lines, without their line ends
    std::size_t rows = 0;               // the complete rows after them
    bool torn = false;                  // a last line without its line end followed
    std::size_t complete_bytes = 0;     // bytes up to the end of the last complete line
};
// How a rows' file is named in messages, and the longest lines it may have: a sweep's first
// line lists every axis's values (at most kMaxAxisValues of up to 24 characters each, on a few
// axes), a row a cell per column (the caller knows how many).
struct RowFileLimits {
    std::string what = "sweep rows";  // the file as messages name it
    bool output_too = false;  // the run's own output, gone on with (see InputFile)
    RunOutputs* outputs = nullptr;  // the run whose input it is (see InputFile), if any
    std::size_t preamble_line_bytes = std::size_t{16} << 20;  // the longest preamble line, bytes
    std::size_t row_bytes = std::size_t{1} << 20;             // the longest row, bytes
};
// Reads a rows' file whose preamble has `preamble_lines` lines a line at a time (a file of
// millions of rows is never held): on_preamble hears the preamble (and may throw to stop),
// then on_row each row. Throws InputError naming the file when it is no regular file, cannot
// be read, has a line longer than its limit or is shorter than its preamble.
RowFileScan scan_row_file(const std::string& path, std::size_t preamble_lines,
                          const std::function<void(const std::vector<std::string>& preamble)>& on_preamble,
                          const std::function<void(const std::string& row)>& on_row, const RowFileLimits& limits = {});
// The first line of a rows' file (what the sweep is), read no further; throws InputError as
// scan_row_file does.
std::string read_first_line(const std::string& path, const RowFileLimits& limits = {});

// The file a sweep appends its rows to as they finish. Each row is written whole with one
// write() and made durable (fdatasync) before append() returns, so a kill at any moment loses at
// most the row being written, and leaves it as a torn last line. Rows may come from several
// threads; they are written one at a time.
class RowLog {
public:
    // A new file at `path` holding `preamble`, made durable, with `mode` less the umask (the
    // mode of the file it will replace, so that its rows are never more readable than that
    // file's). Throws InputError if something is there already (a file, or a link: a log is
    // never written through one).
    static std::unique_ptr<RowLog> create(const std::string& path, const std::vector<std::string>& preamble,
                                          unsigned mode = 0666);
    // The existing file at `path` (not a link), cut back to its first `complete_bytes` (a torn
    // row dropped), to append to.
    static std::unique_ptr<RowLog> reopen(const std::string& path, std::size_t complete_bytes);
    RowLog(const RowLog&) = delete;
    RowLog& operator=(const RowLog&) = delete;
    ~RowLog();
    // Appends `line` and its line end; throws std::runtime_error naming the file on failure.
    void append(const std::string& line);
    // Closes the file and renames it to `target` (the finished sweep), durably: through a link
    // at `target`, keeping the mode of a file it replaces (as AtomicFile does). Given a
    // RunOutputs, held until the run commits; a run that fails leaves the rows where they are.
    void finish(const std::string& target, RunOutputs* outputs = nullptr);
    const std::string& path() const { return path_; }  // where the rows are being written

private:
    RowLog(std::string path, int fd) : path_(std::move(path)), fd_(fd) {}
    std::string path_;
    int fd_ = -1;
    std::mutex lock_;
};

}  // namespace dragon
