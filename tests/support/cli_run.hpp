// Running the dragon executable from a test: exit code, stdout and stderr, each captured in the
// test's own scratch folder (tests run in parallel).
#pragma once

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "support/scratch.hpp"
#include "support/shell.hpp"

extern char** environ;

namespace dragon_test {

// Starts dragon with these arguments, stdout and stderr sent to /dev/null, without waiting for
// it (a test that kills it midway); its pid, or -1.
inline pid_t spawn_dragon(const std::vector<std::string>& args) {
    std::vector<std::string> words = {DRAGON_EXE};
    words.insert(words.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& w : words) argv.push_back(w.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
    pid_t pid = -1;
    const int err = posix_spawn(&pid, DRAGON_EXE, &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    return err == 0 ? pid : -1;
}

struct CliRun {
    int code;
    std::string out, err;
};

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

}  // namespace dragon_test
