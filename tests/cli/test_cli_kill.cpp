// A kill in the middle of writing leaves nothing behind: dragon video is stopped by SIGTERM and
// by SIGINT once its temporary file exists; neither the target nor a temporary file may remain,
// and a target that existed before keeps its old contents.
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "support/cli_run.hpp"
#include "support/scratch.hpp"

namespace {

namespace fs = std::filesystem;

// AtomicFile names its temporary ".<stem>.tmp<pid>-<n><ext>" beside the target.
std::vector<fs::path> temp_files(const fs::path& dir) {
    std::vector<fs::path> out;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.path().filename().string().find(".tmp") != std::string::npos) out.push_back(e.path());
    return out;
}

using dragon_test::spawn_dragon;

// Waits until a temporary file with some bytes in it appears (the encoder is mid-file), or
// the time limit passes or the process ends first. Sanitized builds are several times slower,
// hence the generous limit.
bool wait_for_partial_file(const fs::path& dir, pid_t pid) {
    using namespace std::chrono;
    const auto limit = steady_clock::now() + seconds(120);
    while (steady_clock::now() < limit) {
        for (const fs::path& p : temp_files(dir)) {
            std::error_code ec;
            if (fs::file_size(p, ec) > 0 && !ec) return true;
        }
        int status = 0;
        if (::waitpid(pid, &status, WNOHANG) == pid) return false;
        std::this_thread::sleep_for(milliseconds(20));
    }
    return false;
}

std::string slurp(const fs::path& p) {
    std::ifstream f(p, std::ios::binary);
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

// Kills a long film (1200 frames at 720p, far more than the wait for its first bytes) with
// `sig` once its temporary file has data; checks dragon died of that signal.
void kill_mid_write(const fs::path& target, int sig) {
    const pid_t pid = spawn_dragon({"video", "-o", target.string(), "--size", "1280x720", "--from", "0",
                                    "--to", "400"});
    ASSERT_GT(pid, 0);
    const bool writing = wait_for_partial_file(target.parent_path(), pid);
    if (writing) ::kill(pid, sig);
    else ::kill(pid, SIGKILL);
    int status = 0;
    ASSERT_EQ(::waitpid(pid, &status, 0), pid);
    ASSERT_TRUE(writing) << "dragon video wrote no temporary file (or ended) before the kill";
    ASSERT_TRUE(WIFSIGNALED(status)) << "status " << status;
    EXPECT_EQ(WTERMSIG(status), sig);
}

class KillMidWrite : public ::testing::TestWithParam<int> {};

TEST_P(KillMidWrite, LeavesNoFile) {
    const fs::path dir = dragon_test::scratch_dir();
    for (const auto& e : fs::directory_iterator(dir)) fs::remove_all(e.path());
    const fs::path target = dir / "film.mp4";
    kill_mid_write(target, GetParam());
    EXPECT_FALSE(fs::exists(target));
    EXPECT_TRUE(temp_files(dir).empty()) << temp_files(dir).front();
}

TEST_P(KillMidWrite, KeepsTheOldFileUntouched) {
    const fs::path dir = dragon_test::scratch_dir();
    for (const auto& e : fs::directory_iterator(dir)) fs::remove_all(e.path());
    const fs::path target = dir / "film.mp4";
    const std::string old = "the film from an earlier run\n";
    std::ofstream(target, std::ios::binary) << old;
    kill_mid_write(target, GetParam());
    EXPECT_EQ(slurp(target), old);
    EXPECT_TRUE(temp_files(dir).empty()) << temp_files(dir).front();
}

INSTANTIATE_TEST_SUITE_P(Cli, KillMidWrite, ::testing::Values(SIGTERM, SIGINT, SIGHUP),
                         [](const auto& info) {
                             return std::string(info.param == SIGTERM  ? "SIGTERM"
                                                : info.param == SIGINT ? "SIGINT"
                                                                       : "SIGHUP");
                         });

}  // namespace
