#include "dragon/input_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include <fmt/format.h>

#include "run_outputs.hpp"

namespace dragon {

namespace {

// What a file that is not a regular one is, for the message.
const char* kind_of(mode_t mode) {
    if (S_ISFIFO(mode)) return "a FIFO (a named pipe)";
    if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a regular file";
}

}  // namespace

InputFile::InputFile(const std::string& path, std::string what, const char* expected, bool output_too,
                     RunOutputs* outputs)
    : path_(path), what_(std::move(what)) {
    // Not blocking: opening a FIFO for reading would otherwise wait for a writer for ever.
    fd_ = ::open(path_.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
    if (fd_ < 0) {
        const int err = errno;
        if (err == ENOENT) throw InputError(fmt::format("{} does not exist", named()));
        throw InputError(fmt::format("{} cannot be read: {}", named(), std::strerror(err)));
    }
    struct stat st {};
    if (::fstat(fd_, &st) != 0) {
        const int err = errno;
        ::close(fd_);
        throw InputError(fmt::format("{} cannot be read: {}", named(), std::strerror(err)));
    }
    if (S_ISDIR(st.st_mode) || !S_ISREG(st.st_mode)) {
        ::close(fd_);
        if (S_ISDIR(st.st_mode)) throw InputError(fmt::format("{} is a folder: give {}", named(), expected));
        throw InputError(fmt::format("{} is {}: only a regular file is read", named(), kind_of(st.st_mode)));
    }
    // A regular file never blocks; the flag only mattered for the open.
    ::fcntl(fd_, F_SETFL, ::fcntl(fd_, F_GETFL) & ~O_NONBLOCK);
    if (!output_too) {
        try {
            run_outputs::note_input(outputs, st.st_dev, st.st_ino, what_, path_);
        } catch (...) {
            ::close(fd_);
            throw;
        }
    }
}

InputFile::~InputFile() {
    if (fd_ >= 0) ::close(fd_);
}

std::string InputFile::named() const { return fmt::format("{} '{}'", what_, shown_text(path_, 4096)); }

std::size_t InputFile::read(char* buffer, std::size_t n) {
    for (;;) {
        const ssize_t got = ::read(fd_, buffer, n);
        if (got >= 0) return static_cast<std::size_t>(got);
        if (errno == EINTR) continue;
        // /proc/self/mem, a disk error, a file on a lost network mount: never taken as an end.
        throw InputError(fmt::format("{} cannot be read: {}", named(), std::strerror(errno)));
    }
}

std::string InputFile::read_rest(std::size_t max_bytes, const std::string& limit_words) {
    std::string text;
    char buffer[1 << 16];
    while (const std::size_t got = read(buffer, sizeof buffer)) {
        if (text.size() + got > max_bytes)
            throw InputError(fmt::format("{} is larger than {}, the most a {} may hold", named(), limit_words, what_));
        text.append(buffer, got);
    }
    return text;
}

std::string read_toml_input(const std::string& path, const std::string& what, RunOutputs* outputs) {
    InputFile file(path, what, "a .toml file", false, outputs);
    return file.read_rest(kMaxTomlBytes, "1 MiB");
}

}  // namespace dragon
