// Reading an input file the user named (a scenario, a sweep file, a storyboard, a theme, a
// sweep's rows) without trusting it (the io component): only a regular file is read (a FIFO would block for ever,
// /dev/zero never ends), no more than a limit, checked while reading (a file may grow, or lie
// about its size as /proc files do), and a read that fails is an error naming the file and the
// reason, never an empty file.
#pragma once

#include <cstddef>
#include <string>

#include "dragon/errors.hpp"
#include "dragon/shown_text.hpp"  // the messages' way with the user's text

namespace dragon {

class RunOutputs;  // dragon/atomic_file.hpp

// The most a TOML input (scenario, sweep file, storyboard, theme) may hold: the largest in
// assets/ is 3 KiB, so 1 MiB is room for any file written by hand or by a script, and small
// enough that parsing it stays well under a second and 100 MB.
inline constexpr std::size_t kMaxTomlBytes = std::size_t{1} << 20;

// An input file, opened: a regular file, checked. Throws InputError "<what> '<path>' ..." when
// it does not exist, is a folder ("give <expected>"), is not a regular file (a FIFO, a device, a
// socket), cannot be opened or read (with the system's reason). Closes it when destroyed.
class InputFile {
public:
    // Given a RunOutputs (`outputs`), the file is one of that run's inputs, which no output of
    // the run may be; `output_too`: it is the run's own output, read to be gone on with (a
    // sweep's --resume). Null: a file read outside any run.
    InputFile(const std::string& path, std::string what, const char* expected = "a file", bool output_too = false,
              RunOutputs* outputs = nullptr);
    ~InputFile();
    InputFile(const InputFile&) = delete;
    InputFile& operator=(const InputFile&) = delete;

    // Reads up to `n` bytes into `buffer`; 0 at the end. Throws InputError on a read error.
    std::size_t read(char* buffer, std::size_t n);
    // The rest of the file, at most max_bytes of it: throws InputError naming the file and the
    // limit (in `limit_words`, "1 MiB") when there is more.
    std::string read_rest(std::size_t max_bytes, const std::string& limit_words);

    const std::string& path() const { return path_; }  // as given
    const std::string& what() const { return what_; }  // what the file is, for messages ("the storyboard")
    // "<what> '<path>'", as messages start.
    std::string named() const;

private:
    std::string path_, what_;
    int fd_ = -1;
};

// The whole of a TOML input file (kMaxTomlBytes at most), as InputFile reads it (one of the
// inputs of `outputs`' run, if given).
std::string read_toml_input(const std::string& path, const std::string& what, RunOutputs* outputs = nullptr);

}  // namespace dragon
