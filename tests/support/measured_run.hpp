// Running dragon with its resources measured: wall time, peak resident memory (the child's own,
// from wait4), and a deadline after which it is killed as hung. For the tests that feed it
// hostile files: each must end at once, small, whatever the file.
#pragma once

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "support/cli_run.hpp"

namespace dragon_test {

struct MeasuredRun {
    int code = -1;        // exit code; -1 if killed (hung past the deadline, or a signal)
    bool hung = false;
    std::string out, err;
    long max_rss_kb = 0;  // peak resident memory of dragon itself
    double seconds = 0;   // wall clock
};

inline MeasuredRun run_measured(const std::vector<std::string>& args, double deadline_s = 20.0) {
    const std::filesystem::path dir = scratch_dir();
    const std::string out = (dir / "stdout.txt").string(), err = (dir / "stderr.txt").string();
    std::vector<std::string> words = {DRAGON_EXE};
    words.insert(words.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& w : words) argv.push_back(w.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&actions, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    MeasuredRun r;
    const auto start = std::chrono::steady_clock::now();
    pid_t pid = -1;
    const int spawned = posix_spawn(&pid, DRAGON_EXE, &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0) return r;
    int status = 0;
    struct rusage usage {};
    for (;;) {
        const pid_t done = ::wait4(pid, &status, WNOHANG, &usage);
        if (done == pid) break;
        const double waited = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (waited > deadline_s) {
            ::kill(pid, SIGKILL);
            ::wait4(pid, &status, 0, &usage);
            r.hung = true;
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.code = !r.hung && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.max_rss_kb = usage.ru_maxrss;
    r.out = slurp(out);
    r.err = slurp(err);
    std::filesystem::remove(out);
    std::filesystem::remove(err);
    return r;
}

}  // namespace dragon_test
