// Running the dragon executable from a test: exit code, stdout and stderr, each captured in the
// test's own scratch folder (tests run in parallel).
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "support/scratch.hpp"

namespace dragon_test {

struct CliRun {
    int code;
    std::string out, err;
};

inline std::string slurp(const std::filesystem::path& p) {
    std::ifstream f(p, std::ios::binary);
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

// `dragon ARGS` through the shell (ARGS may quote: "--pitch ''"). `prefix` runs before it in
// the same shell ("ulimit -f 1;"); `stdout_to` replaces the captured stdout ("/dev/full").
inline CliRun run_dragon(const std::string& args, const std::string& prefix = "", const std::string& stdout_to = "") {
    const std::filesystem::path dir = scratch_dir();
    const std::filesystem::path out = dir / "stdout.txt", err = dir / "stderr.txt";
    std::filesystem::remove(out);
    const std::string cmd = prefix + " " + std::string(DRAGON_EXE) + " " + args + " >" +
                            (stdout_to.empty() ? out.string() : stdout_to) + " 2>" + err.string();
    const int status = std::system(cmd.c_str());  // its own shell: a ulimit in `prefix` ends with it
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(out), slurp(err)};
}

// stdout of a shell command (poppler's tools, say), and whether it succeeded.
inline std::pair<bool, std::string> shell_output(const std::string& cmd) {
    std::string out;
    FILE* p = popen(cmd.c_str(), "r");
    if (!p) return {false, ""};
    char buf[4096];
    while (const std::size_t n = std::fread(buf, 1, sizeof buf, p)) out.append(buf, n);
    return {pclose(p) == 0, out};
}

inline int count_lines(const std::string& s) {
    int n = 0;
    for (char c : s) n += c == '\n';
    return n;
}

inline bool contains(const std::string& text, const std::string& word) { return text.find(word) != std::string::npos; }

}  // namespace dragon_test
