// The progress line: drawn on a terminal only, never with --quiet, erased when the work ends.
#include <fcntl.h>
#include <pty.h>
#include <sys/wait.h>
#include <unistd.h>

#include <string>

#include <gtest/gtest.h>

#include "cli/progress.hpp"
#include "support/cli_run.hpp"

using dragon_test::contains;

namespace {

struct PtyRun {
    int code;
    std::string err;  // what the terminal showed
};

// `dragon ARGS` with stderr on a pseudo-terminal (stdout to /dev/null): what a user sees.
PtyRun run_on_terminal(const std::string& args) {
    int master = -1, slave = -1;
    if (::openpty(&master, &slave, nullptr, nullptr, nullptr) != 0) return {-1, "openpty failed"};
    const pid_t pid = ::fork();
    if (pid == 0) {
        ::close(master);
        ::dup2(slave, STDERR_FILENO);
        const int null = ::open("/dev/null", O_WRONLY);
        ::dup2(null, STDOUT_FILENO);
        const std::string cmd = std::string(DRAGON_EXE) + " " + args;
        ::execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
        ::_exit(127);
    }
    ::close(slave);
    std::string seen;
    char buf[4096];
    for (ssize_t n; (n = ::read(master, buf, sizeof buf)) > 0;) seen.append(buf, static_cast<size_t>(n));
    ::close(master);
    int status = 0;
    ::waitpid(pid, &status, 0);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, seen};
}

}  // namespace

// "[######......] " then `rest`: the 24-cell bar with `filled` cells done. (Built by appending:
// GCC 12 warns falsely of overlapping copies in "[" + std::string(...) + ...)
std::string line(int filled, const std::string& rest) {
    std::string out = "[";
    out.append(static_cast<size_t>(filled), '#').append(static_cast<size_t>(24 - filled), '.');
    return out.append("] ").append(rest);
}

TEST(Progress, TheLineSaysHowFarHowFastAndHowLong) {
    using dragon::cli::progress_text;
    // 20 of 80 in 10 s: 2 a second, 60 to go, 30 s left; a quarter of the bar.
    EXPECT_EQ(progress_text("pitches", 20, 80, 10.0), line(6, "20/80 pitches  2/s  0:30 left"));
    EXPECT_EQ(progress_text("frames", 0, 300, 0.0), line(0, "0/300 frames"));
    EXPECT_EQ(progress_text("frames", 300, 300, 4.0), line(24, "300/300 frames  75/s  0:00 left"));
    // 1 of 1000 in 10 s: 0.1 a second, 9990 s to go.
    EXPECT_EQ(progress_text("samples", 1, 1000, 10.0), line(0, "1/1000 samples  0.1/s  166:30 left"));
    // 2345 a second: a whole number, not 2.35e+03.
    EXPECT_EQ(progress_text("samples", 2345, 4690, 1.0), line(12, "2345/4690 samples  2345/s  0:01 left"));
}

TEST(Progress, ShownOnATerminalAndErasedAtTheEnd) {
    // 4001 runs of the dragon to the turning space: about 2.7 s on two cores, well past the
    // half second before the line first appears.
    const PtyRun r = run_on_terminal("min-pitch --grid 0.00005");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(contains(r.err, "/4001 pitches")) << r.err;
    EXPECT_TRUE(contains(r.err, " left")) << r.err;
    // The last thing on the terminal erases the line, for the answers that follow.
    const std::string erase = "\r\x1b[K";
    ASSERT_GE(r.err.size(), erase.size());
    EXPECT_EQ(r.err.substr(r.err.size() - erase.size()), erase);
}

TEST(Progress, QuietDrawsNothing) {
    const PtyRun r = run_on_terminal("min-pitch --grid 0.002 --quiet");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.err, "");
}

TEST(Progress, NotDrawnWhenStderrIsNotATerminal) {
    const auto r = dragon_test::run_dragon("min-pitch --grid 0.002");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.err, "");
}
