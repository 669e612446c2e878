// A sweep's rows on disk: reading a rows' file back (dropping a torn last line), and the durable
// append-only log rows are written to as they finish.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include <fmt/format.h>

#include "file_placement.hpp"
#include "run_outputs.hpp"
#include "dragon/input_file.hpp"
#include "dragon/row_files.hpp"

namespace dragon {

RowFileScan scan_row_file(const std::string& path, std::size_t preamble_lines,
                          const std::function<void(const std::vector<std::string>&)>& on_preamble,
                          const std::function<void(const std::string&)>& on_row, const RowFileLimits& limits) {
    InputFile file(path, limits.what, "a .csv file", limits.output_too, limits.outputs);
    RowFileScan out;
    bool heard = false;
    std::size_t number = 0;  // of the line being read
    std::string line;
    char buffer[1 << 16];
    std::size_t have = 0, at = 0;
    bool end = false;
    for (;;) {
        // One line, never longer than its limit: a line of NULs or a 10 MB row is refused as it
        // is read, not held whole.
        ++number;
        line.clear();
        const std::size_t most = out.preamble.size() < preamble_lines ? limits.preamble_line_bytes : limits.row_bytes;
        bool complete = false;
        while (!complete) {
            if (at == have) {
                if (end) break;
                have = file.read(buffer, sizeof buffer), at = 0;
                if (have == 0) {
                    end = true;
                    break;
                }
            }
            const char* start = buffer + at;
            const auto* nl = static_cast<const char*>(std::memchr(start, '\n', have - at));
            const std::size_t take = nl ? static_cast<std::size_t>(nl - start) : have - at;
            if (line.size() + take > most)
                throw InputError(fmt::format("{}: line {} is longer than {} bytes, the most a {} of it may hold",
                                             file.named(), number, most,
                                             out.preamble.size() < preamble_lines ? "first line" : "row"));
            line.append(start, take);
            at += take;
            if (nl) ++at, complete = true;
        }
        if (!complete) {
            out.torn = !line.empty();  // written up to a kill: not a row
            break;
        }
        out.complete_bytes += line.size() + 1;
        // A sweep ends its lines with LF alone: a CR before it is an edit, and taking the line
        // without it would leave CR LF and LF lines mixed in the finished file.
        if (!line.empty() && line.back() == '\r')
            throw InputError(fmt::format("{}: line {} ends in CR LF, and a sweep's lines end in LF alone (was it "
                                         "edited elsewhere?)", file.named(), number));
        if (out.preamble.size() < preamble_lines) {
            out.preamble.push_back(line);
            continue;
        }
        if (!heard) on_preamble(out.preamble), heard = true;
        ++out.rows;
        on_row(line);
    }
    if (out.preamble.size() < preamble_lines)
        throw InputError(fmt::format("{} is not a sweep's rows: it has {} complete line{}, and a sweep's file "
                                     "starts with {}", file.named(), out.preamble.size(),
                                     out.preamble.size() == 1 ? "" : "s", preamble_lines));
    if (!heard) on_preamble(out.preamble);
    return out;
}

std::string read_first_line(const std::string& path, const RowFileLimits& limits) {
    InputFile file(path, limits.what, "a .csv file", limits.output_too, limits.outputs);
    std::string line;
    // Only the first line is wanted: reading stops at its end.
    char buffer[4096];
    for (;;) {
        const std::size_t got = file.read(buffer, sizeof buffer);
        if (got == 0) break;
        const auto* nl = static_cast<const char*>(std::memchr(buffer, '\n', got));
        const std::size_t take = nl ? static_cast<std::size_t>(nl - buffer) : got;
        if (line.size() + take > limits.preamble_line_bytes)
            throw InputError(fmt::format("{}: its first line is longer than {} bytes, the most it may hold",
                                         file.named(), limits.preamble_line_bytes));
        line.append(buffer, take);
        if (nl) return line;
    }
    throw InputError(fmt::format("{} is not a sweep's rows: it has no complete first line", file.named()));
}

namespace {

FileError failure(const std::string& path, const char* what) {
    return FileError(path, "write", what);
}

// Writes all of `text` (write() may take less than asked) and makes it durable.
void write_durably(int fd, const std::string& text, const std::string& path) {
    std::size_t done = 0;
    while (done < text.size()) {
        const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) throw failure(path, std::strerror(n < 0 ? errno : EIO));
        done += static_cast<std::size_t>(n);
    }
    if (::fdatasync(fd) != 0) throw failure(path, std::strerror(errno));
}

}  // namespace

std::unique_ptr<RowLog> RowLog::create(const std::string& path, const std::vector<std::string>& preamble,
                                       unsigned mode) {
    // A new file (never through a link left there): its mode follows the umask, as any new file's.
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_APPEND | O_CLOEXEC | O_NOFOLLOW,
                          static_cast<mode_t>(mode & 0777));
    if (fd < 0) throw InputError(fmt::format("output '{}' cannot be made: {}", path, std::strerror(errno)));
    std::unique_ptr<RowLog> log(new RowLog(path, fd));
    std::string text;
    for (const std::string& line : preamble) text += line + "\n";
    write_durably(fd, text, path);
    placement::sync_folder_of(path);
    return log;
}

std::unique_ptr<RowLog> RowLog::reopen(const std::string& path, std::size_t complete_bytes) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC | O_NOFOLLOW);
    if (fd < 0) throw InputError(fmt::format("'{}' cannot be written to: {}", path, std::strerror(errno)));
    std::unique_ptr<RowLog> log(new RowLog(path, fd));
    // A torn last row goes: the next row must start on a line of its own.
    if (::ftruncate(fd, static_cast<off_t>(complete_bytes)) != 0 || ::fdatasync(fd) != 0)
        throw failure(path, std::strerror(errno));
    return log;
}

RowLog::~RowLog() {
    if (fd_ >= 0) ::close(fd_);
}

void RowLog::append(const std::string& line) {
    const std::lock_guard<std::mutex> hold(lock_);
    // One write() for the whole line: a kill leaves it whole or torn, never two rows interleaved.
    write_durably(fd_, line + "\n", path_);
}

void RowLog::finish(const std::string& target, RunOutputs* outputs) {
    const std::lock_guard<std::mutex> hold(lock_);
    if (::close(fd_) != 0) {
        fd_ = -1;
        throw failure(path_, std::strerror(errno));
    }
    fd_ = -1;
    placement::Placement p;
    try {
        p = {path_, placement::resolve_target(target), target, 0644, true};
    } catch (const InputError& e) {
        throw failure(target, e.what());  // checked before the run; changed since
    }
    struct stat st {};
    if (::stat(path_.c_str(), &st) == 0) p.new_mode = st.st_mode & 0777;  // made with 0666 less the umask
    if (run_outputs::hold(outputs, p, -1)) return;
    placement::place_all({p});
}

}  // namespace dragon
