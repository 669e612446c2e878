// dragon video end to end: bad options exit 2 and leave nothing behind; a good run writes the film.
#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <ostream>
#include <string>

#include <gtest/gtest.h>

#include "support/scratch.hpp"

namespace fs = std::filesystem;

namespace {

fs::path scratch_dir() { return dragon_test::scratch_dir(); }

struct RunResult {
    int code;
    std::string out, err;
};

RunResult dragon_video(const std::string& args) {
    const fs::path dir = scratch_dir();
    const std::string out = (dir / "stdout.txt").string(), err = (dir / "stderr.txt").string();
    const std::string cmd = std::string(DRAGON_EXE) + " video " + args + " >" + out + " 2>" + err;
    const int status = std::system(cmd.c_str());
    const auto slurp = [](const std::string& p) {
        std::ifstream f(p);
        std::stringstream ss;
        ss << f.rdbuf();
        return ss.str();
    };
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(out), slurp(err)};
}

// Files in the scratch folder other than the captured output: targets and temporaries alike.
int stray_files() {
    int n = 0;
    for (const auto& e : fs::directory_iterator(scratch_dir())) {
        const std::string name = e.path().filename().string();
        n += name != "stdout.txt" && name != "stderr.txt";
    }
    return n;
}

struct BadCase {
    const char* name;
    std::string args;  // after -o FILE
    std::string file;
    const char* message;  // a word the one-line error must contain
};

// Shown by gtest in test names and failures, instead of the object's bytes.
void PrintTo(const BadCase& c, std::ostream* os) { *os << c.name << ": " << c.args; }

class BadOptions : public ::testing::TestWithParam<BadCase> {};

TEST_P(BadOptions, ExitTwoAndNoFile) {
    const BadCase c = GetParam();
    for (const auto& e : fs::directory_iterator(scratch_dir())) fs::remove_all(e.path());
    const std::string target = c.file.front() == '/' ? c.file : (scratch_dir() / c.file).string();
    const RunResult r = dragon_video("-o " + target + " " + c.args);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(target));
    EXPECT_EQ(stray_files(), 0);
}

// Small and short, so a case that wrongly succeeded would still finish quickly.
const std::string ok = " --size 64x48 --fps 5 --from 0 --to 1";

INSTANTIATE_TEST_SUITE_P(
    Video, BadOptions,
    ::testing::Values(BadCase{"odd_width", "--size 65x48 --to 1", "a.mp4", "even"},
                      BadCase{"odd_height", "--size 64x47 --to 1", "a.webm", "even"},
                      BadCase{"unknown_extension", ok, "a.avi", ".avi"},
                      BadCase{"no_extension", ok, "film", "extension"},
                      BadCase{"unwritable_path", ok, "/nonexistent-dragon-dir/a.mp4", "not writable"},
                      BadCase{"fps_zero", "--fps 0 --to 1", "a.mp4", "--fps"},
                      BadCase{"empty_range", "--size 64x48 --from 5 --to 5", "a.mp4", "empty"},
                      BadCase{"reversed_range", "--size 64x48 --from 5 --to 2", "a.gif", "empty"},
                      BadCase{"past_the_centre", "--size 64x48 --to 100000", "a.mp4", "--to"},
                      BadCase{"bad_to", "--size 64x48 --to soon", "a.mp4", "--to"},
                      BadCase{"bad_size", "--size big --to 1", "a.mp4", "--size"},
                      BadCase{"bad_preset", ok + " --preset glacial", "a.mp4", "--preset"},
                      BadCase{"bad_colours", ok + " --colours 1", "a.gif", "--colours"},
                      BadCase{"bad_speedup", ok + " --speedup -1", "a.mp4", "--speedup"},
                      // -1 is no codec's quality: there is no "default" value to give.
                      BadCase{"crf_minus_one", ok + " --crf -1", "a.mp4", "--crf -1 is not allowed for H.264"},
                      BadCase{"crf_for_gif", ok + " --crf 20", "a.gif", "--crf 20 is not allowed for .gif"},
                      BadCase{"preset_for_webm", ok + " --preset fast", "a.webm", "--preset fast is not allowed: a preset is libx264's, for .mp4, not .webm"},
                      BadCase{"bad_tune", ok + " --tune cartoon", "a.mp4", "--tune cartoon is not allowed"},
                      BadCase{"tune_for_gif", ok + " --tune film", "a.gif", "--tune film is not allowed: a tune is libx264's, for .mp4, not .gif"},
                      // 8192x8192 is 262,144 macroblocks: past H.264's largest level; VP9 takes it.
                      BadCase{"beyond_h264_levels", "--size 8192x8192 --fps 5 --to 1", "a.mp4",
                              "H.264 allows at most 139264 macroblocks"},
                      BadCase{"colours_for_mp4", ok + " --colours 64", "a.mp4", "--colours 64 is not allowed: it sets a GIF's palette, for .gif, not .mp4"},
                      // A rate the muxer cannot time: refused before it is asked.
                      BadCase{"fps_tiny", "--size 64x48 --fps 1e-9 --to 1", "a.mp4",
                              "--fps 1e-09 is not allowed: use a rate from 0.01 to 240"},
                      BadCase{"speedup_tiny", "--size 64x48 --speedup 1e-300 --to 1", "a.mp4",
                              "the film would have 3e+301 frames"},
                      BadCase{"hold_over_an_hour", ok + " --hold 3601", "a.mp4", "--hold 3601"},
                      BadCase{"zoom_nan", ok + " --zoom nan", "a.mp4", "--zoom nan"},
                      BadCase{"zoom_huge", ok + " --zoom 1e300", "a.mp4", "--zoom 1e+300"},
                      // 8.8 m out, doubles cannot resolve pixels of 1e-9 / 720 m.
                      BadCase{"zoom_too_fine", "--size 1280x720 --fps 5 --to 1 --follow-head --zoom 1e-9", "a.mp4",
                              "--zoom 1e-09"}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(CliVideo, TheSlowestRateWorksForEveryFormat) {
    for (const char* name : {"slow.mp4", "slow.webm", "slow.gif"}) {
        const std::string target = (scratch_dir() / name).string();
        const RunResult r = dragon_video("-o " + target + " --size 64x48 --fps 0.01 --speedup 0.01 --to 1 -q");
        EXPECT_EQ(r.code, 0) << name << ": " << r.err;
        EXPECT_EQ(r.err, "") << name;
        EXPECT_TRUE(fs::exists(target)) << name;
    }
}

TEST(CliVideo, WritesTheFilmAndSaysSo) {
    for (const auto& e : fs::directory_iterator(scratch_dir())) fs::remove_all(e.path());
    const std::string target = (scratch_dir() / "coil.mp4").string();
    const RunResult r = dragon_video("-o " + target + " --size 96x64 --fps 10 --speedup 5 --from 0 --to 2");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(fs::exists(target));
    EXPECT_GT(fs::file_size(target), 0u);
    // Status on stderr, as for every command; stdout is for answers (none here).
    EXPECT_EQ(r.out, "");
    // 0, 0.5, 1, 1.5, 2 s. stderr is not a terminal here: no progress line, and no codec chatter.
    EXPECT_EQ(r.err.rfind("wrote " + target + ": 5 frames", 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_EQ(stray_files(), 1);
    const RunResult quiet = dragon_video("-o " + target + " --size 96x64 --fps 10 --speedup 5 --from 0 --to 2 -q");
    ASSERT_EQ(quiet.code, 0) << quiet.err;
    EXPECT_EQ(quiet.err, "");
}

}  // namespace
