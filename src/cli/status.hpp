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

// The lines saying that a file was written, held until the run's files are in place: a command's
// outputs are put in place only when the whole run has succeeded (main commits its RunOutputs,
// then prints these), so a run that fails never says "wrote".
inline std::vector<std::string>& held_status_lines() {
    static std::vector<std::string> lines;
    return lines;
}
inline void print_held_status_lines() {
    for (const std::string& line : held_status_lines()) fmt::print(stderr, "{}\n", line);
    held_status_lines().clear();
}

// One status line on stderr, unless quiet: one line whatever a name in it holds (-o $'a\nb.csv'
// is shown as a\nb.csv). A line that reports a written file ("wrote ...") is held until the
// file is in place (above).
template <typename... A>
void status(bool quiet, fmt::format_string<A...> f, A&&... args) {
    if (quiet) return;
    const std::string line = shown_text(fmt::format(f, std::forward<A>(args)...), 8192);
    if (line.rfind("wrote ", 0) == 0) held_status_lines().push_back(line);
    else fmt::print(stderr, "{}\n", line);
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
