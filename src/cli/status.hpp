// What a command says on stderr besides errors: "wrote FILE ..." lines. stdout holds answers
// (tables, JSON, the paper-style text) and nothing else, so it can be piped or redirected;
// status goes to stderr for every command, and --quiet silences it (and the progress line).
#pragma once

#include <cerrno>
#include <cstdio>
#include <system_error>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "dragon/input_file.hpp"

namespace dragon::cli {

inline void add_quiet_flag(CLI::App* sub, bool& quiet) {
    sub->add_flag("-q,--quiet", quiet, "Nothing on stderr but errors and warnings: no progress line, no 'wrote' lines");
}

// One status line on stderr, unless quiet: one line whatever a name in it holds (-o $'a\nb.csv'
// is shown as a\nb.csv). A line saying a file was written is not one of these: it waits for
// the file to be in place (ToolRun::wrote, commands.hpp).
template <typename... A>
void status(bool quiet, fmt::format_string<A...> f, A&&... args) {
    if (!quiet) fmt::print(stderr, "{}\n", shown_text(fmt::format(f, std::forward<A>(args)...), 8192));
}

// Each warning of a file that used an old name, one line each on stderr: "dragon: warning: ...".
// Printed with --quiet too, as the notes about an answer are: the file works today, and will not
// when the old names go.
inline void print_warnings(const KeyWarnings& warnings) {
    for (const KeyWarning& w : warnings) fmt::print(stderr, "dragon: warning: {}\n", shown_text(w.message, 8192));
}

// Throws std::system_error if what was printed on stdout did not all reach it (a full disk, a
// closed pipe): a command that commits files last calls it first, so such a run changes none.
inline void require_stdout_written() {
    if (std::fflush(stdout) != 0 || std::ferror(stdout) != 0)
        throw std::system_error(errno, std::generic_category(), "standard output");
}

}  // namespace dragon::cli
