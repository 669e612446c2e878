// A sweep's rows on disk: CSV fields, reading a rows' file back (dropping a torn last line), and
// the durable append-only log rows are written to as they finish.
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>

#include "dragon/sweep.hpp"

namespace dragon {

std::string csv_field(std::string_view text) {
    if (text.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(text);
    std::string out = "\"";
    for (char c : text) {
        if (c == '"') out += '"';
        out += c;
    }
    return out + "\"";
}

std::string csv_line(const std::vector<std::string>& fields) {
    std::string out;
    for (std::size_t k = 0; k < fields.size(); ++k) {
        if (k) out += ',';
        out += csv_field(fields[k]);
    }
    return out;
}

std::vector<std::string> split_csv(std::string_view line) {
    std::vector<std::string> out(1);
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quoted) {
            if (c != '"') out.back() += c;
            else if (i + 1 < line.size() && line[i + 1] == '"') out.back() += '"', ++i;
            else quoted = false;
        } else if (c == '"') {
            quoted = true;
        } else if (c == ',') {
            out.emplace_back();
        } else {
            out.back() += c;
        }
    }
    if (quoted) throw InputError(fmt::format("a CSV line has an unclosed quote: {:.60}", line));
    return out;
}

RowFileScan scan_row_file(const std::string& path, std::size_t preamble_lines,
                          const std::function<void(const std::vector<std::string>&)>& on_preamble,
                          const std::function<void(const std::string&)>& on_row) {
    std::ifstream in(path, std::ios::binary);
    std::error_code ec;
    if (!in || std::filesystem::is_directory(path, ec)) throw InputError(fmt::format("'{}' cannot be read", path));
    RowFileScan out;
    bool heard = false;
    for (std::string line; std::getline(in, line);) {
        if (in.eof()) {
            out.torn = true;  // written up to a kill: not a row
            break;
        }
        out.complete_bytes += line.size() + 1;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (out.preamble.size() < preamble_lines) {
            out.preamble.push_back(std::move(line));
            continue;
        }
        if (!heard) on_preamble(out.preamble), heard = true;
        ++out.rows;
        on_row(line);
    }
    if (out.preamble.size() < preamble_lines)
        throw InputError(fmt::format("'{}' is not a sweep's rows: it has {} complete line{}, and a sweep's file "
                                     "starts with {}", path, out.preamble.size(), out.preamble.size() == 1 ? "" : "s",
                                     preamble_lines));
    if (!heard) on_preamble(out.preamble);
    return out;
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

// The folder's entry for a file made or renamed in it, made durable too.
void sync_folder(const std::string& path) {
    std::filesystem::path dir = std::filesystem::path(path).parent_path();
    if (dir.empty()) dir = ".";
    const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return;  // a folder that cannot be opened for reading: the rename still stands
    ::fsync(fd);
    ::close(fd);
}

}  // namespace

std::unique_ptr<RowLog> RowLog::create(const std::string& path, const std::vector<std::string>& preamble) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_APPEND | O_CLOEXEC, 0644);
    if (fd < 0) throw InputError(fmt::format("output '{}' cannot be made: {}", path, std::strerror(errno)));
    std::unique_ptr<RowLog> log(new RowLog(path, fd));
    std::string text;
    for (const std::string& line : preamble) text += line + "\n";
    write_durably(fd, text, path);
    sync_folder(path);
    return log;
}

std::unique_ptr<RowLog> RowLog::reopen(const std::string& path, std::size_t complete_bytes) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
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

void RowLog::finish(const std::string& target) {
    const std::lock_guard<std::mutex> hold(lock_);
    if (::close(fd_) != 0) {
        fd_ = -1;
        throw failure(path_, std::strerror(errno));
    }
    fd_ = -1;
    if (std::rename(path_.c_str(), target.c_str()) != 0) throw failure(target, std::strerror(errno));
    sync_folder(target);
}

}  // namespace dragon
