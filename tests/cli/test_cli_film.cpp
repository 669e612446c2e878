// dragon film end to end: a storyboard becomes a film or a poster frame; bad storyboards and
// options exit 2 with one line naming the shot and key, and leave no file.
#include <filesystem>
#include <fstream>
#include <ostream>
#include <string>

#include <gtest/gtest.h>

#include "support/cli_run.hpp"

namespace fs = std::filesystem;
using dragon_test::run_dragon;

namespace {

// Files in the scratch folder but the captured output and the storyboard: targets and temporaries.
int stray_files() {
    int n = 0;
    for (const auto& e : fs::directory_iterator(dragon_test::scratch_dir())) {
        const std::string name = e.path().filename().string();
        n += name != "stdout.txt" && name != "stderr.txt" && name != "story.toml";
    }
    return n;
}

std::string write_story(const std::string& text) {
    const fs::path p = dragon_test::scratch_dir() / "story.toml";
    std::ofstream(p) << text;
    return p.string();
}

const std::string small = "[film]\nsize = \"96x64\"\nfps = 5\n";

TEST(CliFilm, WritesTheFilmAndAPosterFrame) {
    for (const auto& e : fs::directory_iterator(dragon_test::scratch_dir())) fs::remove_all(e.path());
    const std::string story = write_story(small + "[[shot]]\ntitle = \"Hi\"\nduration = 1\n"
                                                  "[[shot]]\nfrom = 10\nto = 12\nrate = 2\n");
    const std::string film = (dragon_test::scratch_dir() / "f.gif").string();
    const auto r = run_dragon("film " + story + " -o " + film);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.out, "");
    // 5 frames of card, 2 s of motion at 2 s per second: 6 frames.
    EXPECT_EQ(r.err.rfind("wrote " + film + ": 2 shots, 11 frames, 96x64, 2.20 s of film", 0), 0u) << r.err;
    const std::string poster = (dragon_test::scratch_dir() / "p.png").string();
    const auto p = run_dragon("film " + story + " -o " + poster + " --at 1.5 -q");
    ASSERT_EQ(p.code, 0) << p.err;
    EXPECT_EQ(p.err, "");
    EXPECT_GT(fs::file_size(poster), 100u);
    EXPECT_EQ(stray_files(), 2);
}

struct BadCase {
    const char* name;
    std::string story;  // "" : the good one
    std::string args;   // after the storyboard and -o FILE
    std::string file;
    std::string message;
};
void PrintTo(const BadCase& c, std::ostream* os) { *os << c.name; }

class BadFilm : public ::testing::TestWithParam<BadCase> {};

TEST_P(BadFilm, ExitTwoOneLineAndNoFile) {
    for (const auto& e : fs::directory_iterator(dragon_test::scratch_dir())) fs::remove_all(e.path());
    const BadCase& c = GetParam();
    const std::string story = c.story == "MISSING"
                                  ? (dragon_test::scratch_dir() / "nowhere.toml").string()
                                  : write_story(small + (c.story.empty() ? "[[shot]]\nfrom = 10\nto = 12\nrate = 2\n" : c.story));
    const auto r = run_dragon("film " + story + " -o " + (dragon_test::scratch_dir() / c.file).string() + " " + c.args);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_EQ(dragon_test::count_lines(r.err), 1) << r.err;
    EXPECT_TRUE(dragon_test::contains(r.err, c.message)) << r.err;
    EXPECT_EQ(stray_files(), 0);
    fs::remove(dragon_test::scratch_dir() / "story.toml");
}

INSTANTIATE_TEST_SUITE_P(
    Film, BadFilm,
    ::testing::Values(
        BadCase{"unknown_key", "[[shot]]\nname = \"a\"\nfrom = 1\nto = 2\nrate = 1\nspeeed = 2\n", "", "f.mp4",
                "shot 1 (\"a\"): speeed is not a key of a shot"},
        BadCase{"past_the_valid_range", "[[shot]]\nfrom = 430\nto = 440\nrate = 5\n", "", "f.mp4",
                "shot 1, key 'to': to 440 is not allowed: the dragon can follow its path only until"},
        BadCase{"overlapping_transitions",
                "[[shot]]\nfrom = 0\nto = 2\nrate = 2\n[[shot]]\nfrom = 0\nto = 0.5\nrate = 2\ntransition = { crossfade = 0.4 }\n"
                "[[shot]]\nfrom = 0\nto = 2\nrate = 2\ntransition = { crossfade = 0.4 }\n",
                "", "f.mp4", "shot 3, key 'transition': its crossfade overlaps the one into shot 2"},
        BadCase{"png_without_at", "", "", "f.png", "give --at SECONDS"},
        BadCase{"at_past_the_end", "", "--at 99", "f.png", "--at 99 is not allowed: the film lasts 1.200 s"},
        BadCase{"at_for_a_film", "", "--at 1", "f.mp4", "--at 1 is not allowed for a film"},
        BadCase{"poster_not_png", "", "--at 1", "p.svg", "p.svg has extension '.svg': the frame --at 1 picks is written as a .png"},
        BadCase{"tune_for_webm", "", "--tune film", "f.webm", "--tune film is not allowed: a tune is libx264's, for .mp4, not .webm"},
        BadCase{"odd_size", "", "--size 97x64", "f.mp4", "yuv420p, which needs an even width"},
        BadCase{"bad_extension", "", "", "f.avi", "videos are .mp4"},
        BadCase{"missing_storyboard", "MISSING", "", "f.mp4", "nowhere.toml' does not exist"}),
    [](const auto& info) { return std::string(info.param.name); });

}  // namespace
