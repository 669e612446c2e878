// Shell helpers for tests that need no dragon executable (a component's own tests read its files
// back with poppler's tools, say): a command's stdout, and small text checks.
#pragma once

#include <cstdio>
#include <string>
#include <utility>

namespace dragon_test {

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
