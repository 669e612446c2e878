// Storyboards read into data, and every kind of bad input named by its shot and key.
#include <gtest/gtest.h>

#include <fstream>
#include <ostream>

#include "dragon/film.hpp"
#include "support/scratch.hpp"

using namespace dragon;

namespace {

const std::string assets = std::string(DRAGON_SOURCE_DIR) + "/assets";

Storyboard parse(const std::string& text) { return parse_storyboard(text, "s.toml", DRAGON_SOURCE_DIR, assets); }

TEST(Storyboard, ReadsShotsOfEveryKind) {
    const Storyboard b = parse(R"(
[film]
size = "320x180"
fps = 12
[[shot]]
name = "card"
title = "Hello"
subtitle = "world"
duration = 2
[[shot]]
from = "boundary - 30"
to = "collision"
rate = 20
pitch = 0.5
camera = { from = "fit", to = { follow = 8 }, ease = "linear" }
slow = { at = "collision", within = 2, rate = 0.5 }
freeze = { seconds = 1.5, zoom = 2 }
captions = [{ text = "look", at = "collision-1", seconds = 2 }]
transition = { crossfade = 0.5 }
[[shot]]
path = "turnaround"
duration = 4
split = [{ arc_ratio = 1.5, label = "left" }, { from = -5, to = "end - 0" , arc_ratio = 2.5 }]
)");
    EXPECT_EQ(b.film.width, 320);
    EXPECT_EQ(b.film.height, 180);
    EXPECT_EQ(b.film.fps, 12);
    ASSERT_EQ(b.shots.size(), 3u);
    EXPECT_EQ(b.shots[0].kind, Shot::Kind::title);
    EXPECT_EQ(b.shots[0].name, "\"card\"");
    const Shot& s = b.shots[1];
    EXPECT_EQ(s.kind, Shot::Kind::scene);
    EXPECT_EQ(s.name, "shot 2");
    ASSERT_EQ(s.views.size(), 1u);
    EXPECT_EQ(s.views[0].scenario.path.pitch, 0.5);
    EXPECT_EQ(s.views[0].from.anchor, TimeRef::Anchor::boundary);
    EXPECT_EQ(s.views[0].from.offset, -30.0);
    EXPECT_EQ(s.views[0].to.anchor, TimeRef::Anchor::collision);
    EXPECT_EQ(s.views[0].camera.from.kind, Window::Kind::fit);
    ASSERT_TRUE(s.views[0].camera.to);
    EXPECT_EQ(s.views[0].camera.to->kind, Window::Kind::head);
    EXPECT_EQ(s.views[0].camera.to->extent, 8.0);
    EXPECT_EQ(s.views[0].camera.ease, Ease::linear);
    ASSERT_TRUE(s.slow);
    EXPECT_EQ(s.slow->rate, 0.5);
    EXPECT_EQ(s.freeze.zoom, 2.0);
    ASSERT_EQ(s.captions.size(), 1u);
    EXPECT_EQ(s.captions[0].at->offset, -1.0);
    EXPECT_EQ(s.crossfade, 0.5);
    const Shot& split = b.shots[2];
    EXPECT_EQ(split.kind, Shot::Kind::split);
    ASSERT_EQ(split.views.size(), 2u);
    EXPECT_EQ(split.views[0].scenario.path.kind, PathKind::turnaround);  // the shot's key, shared
    EXPECT_EQ(split.views[0].scenario.path.arc_ratio, 1.5);
    EXPECT_EQ(split.views[1].scenario.path.arc_ratio, 2.5);
    EXPECT_EQ(split.views[0].label, "left");
    EXPECT_FALSE(split.views[1].label);  // unset: the scenario in words
    // The turnaround's own default range, and the pane's.
    EXPECT_EQ(split.views[0].from.offset, -100.0);
    EXPECT_EQ(split.views[1].from.offset, -5.0);
    EXPECT_EQ(split.views[1].to.anchor, TimeRef::Anchor::end);
}

struct Bad {
    const char* name;
    std::string toml;
    std::string says;  // the message must contain this
};
// Shown by gtest in failures, instead of the object's bytes.
void PrintTo(const Bad& c, std::ostream* os) { *os << c.name; }

class BadStoryboard : public ::testing::TestWithParam<Bad> {};

TEST_P(BadStoryboard, NamesTheShotAndTheKey) {
    try {
        parse(GetParam().toml);
        FAIL() << "accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(GetParam().says), std::string::npos) << e.what();
        EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << "one line: " << e.what();
    }
}

const std::string ok_shot = "[[shot]]\nfrom = 0\nto = 10\nrate = 5\n";

INSTANTIATE_TEST_SUITE_P(
    Storyboard, BadStoryboard,
    ::testing::Values(
        Bad{"unknown_key", ok_shot + "zoom = 3\n", "shot 1: zoom is not a key of a shot"},
        Bad{"unknown_film_key", "[film]\nwidth = 3\n" + ok_shot, "[film] width is not a key of [film]"},
        Bad{"unknown_section", "[films]\n" + ok_shot, "films"},
        Bad{"no_shots", "[film]\nfps = 10\n", "at least one [[shot]]"},
        Bad{"bad_moment", "[[shot]]\nfrom = \"soon\"\nto = 10\nrate = 5\n", "key 'from': 'soon' is not a moment"},
        Bad{"bad_offset", "[[shot]]\nfrom = \"collision * 2\"\nto = 10\nrate = 5\n", "key 'from'"},
        Bad{"rate_and_duration", ok_shot + "duration = 3\n", "key 'duration': give a rate"},
        Bad{"neither", "[[shot]]\nfrom = 0\nto = 10\n", "key 'rate'"},
        Bad{"negative_rate", "[[shot]]\nfrom = 0\nto = 10\nrate = -5\n", "shot 1: rate = -5 is not allowed"},
        Bad{"title_without_duration", "[[shot]]\ntitle = \"x\"\n", "key 'duration': a title card needs a duration"},
        Bad{"title_with_from", "[[shot]]\ntitle = \"x\"\nduration = 2\nfrom = 3\n", "shot 1: from is not a key of a title card"},
        Bad{"bad_camera", ok_shot + "camera = \"close\"\n", "key 'camera': 'close' is not a window"},
        Bad{"bad_camera_move", ok_shot + "camera = { from = \"fit\", to = { follow = -1 } }\n",
            "camera.to.follow = -1 is not allowed"},
        Bad{"bad_ease", ok_shot + "camera = { from = \"fit\", ease = \"bounce\" }\n", "key 'camera.ease'"},
        Bad{"bad_transition", ok_shot + "transition = \"wipe\"\n", "shot 1: transition must be \"cut\" or {crossfade"},
        Bad{"split_of_one", "[[shot]]\nrate = 5\nsplit = [{ pitch = 0.5 }]\n", "split must list two scenes"},
        Bad{"split_pane_key", "[[shot]]\nrate = 5\nsplit = [{ pitch = 0.5 }, { rate = 3 }]\n",
            "split[2].rate is not a key of a split scene"},
        Bad{"slow_in_split", "[[shot]]\nrate = 5\nslow = { at = 1, within = 1, rate = 1 }\nsplit = [{}, {}]\n",
            "slow is not allowed in a split shot"},
        Bad{"bad_pitch", ok_shot + "pitch = 0.2\n", "key 'pitch': pitch 0.2 is not allowed"},
        Bad{"unknown_preset", ok_shot + "scenario = \"nowhere\"\n", "key 'scenario': 'nowhere' is neither a preset"},
        Bad{"bad_path", ok_shot + "path = \"circle\"\n", "key 'path': 'circle' is not a path"},
        Bad{"caption_without_text", ok_shot + "captions = [{ at = 3 }]\n", "captions[1] must be a table with text"},
        Bad{"bad_size", "[film]\nsize = \"big\"\n" + ok_shot, "[film] size: 'big' is not allowed"},
        // The sizes and rates a video can take, named by the storyboard's key, not a flag.
        Bad{"small_size", "[film]\nsize = \"8x8\"\n" + ok_shot,
            "[film] size: '8x8' is not allowed: each side must be 16..8192 px"},
        Bad{"huge_size", "[film]\nsize = \"9000x9000\"\n" + ok_shot,
            "[film] size: '9000x9000' is not allowed: each side must be 16..8192 px"},
        Bad{"slow_fps", "[film]\nfps = 0.005\n" + ok_shot,
            "[film] fps = 0.005 is not allowed: use a rate from 0.01 to 240 frames per second"},
        Bad{"fast_fps", "[film]\nfps = 300\n" + ok_shot, "[film] fps = 300 is not allowed"},
        Bad{"not_toml", "[[shot]\n", "is not valid TOML"},
        Bad{"bad_lang", "[film]\nlang = \"fr\"\n" + ok_shot, "[film] lang: \"fr\" is not allowed: use en (English) or zh"},
        Bad{"bad_width", ok_shot + "width = 0\n", "key 'width'"},
        Bad{"hole_past_the_board", ok_shot + "hole_offset = 1.2\n", "key 'hole_offset'"},
        Bad{"fractional_count", ok_shot + "bench_count = 2.5\n", "shot 1: bench_count must be a whole number"},
        // A moment of the wrong type is named as one, not as an empty moment.
        Bad{"moment_of_a_list", "[[shot]]\nfrom = [1]\nto = 10\nrate = 5\n",
            "shot 1: from must be a moment: a number of seconds, or a string"},
        // [film]'s scenario is [film]'s fault, not the first shot's.
        Bad{"film_scenario", "[film]\nscenario = \"nowhere.toml\"\n" + ok_shot,
            "[film] scenario: scenario file '" + std::string(DRAGON_SOURCE_DIR) + "/nowhere.toml' does not exist"},
        // Limits that keep reading and drawing bounded, each named by its key.
        Bad{"too_many_shots", [] {
                std::string t;
                for (std::size_t i = 0; i <= kMaxStoryboardShots; ++i) t += "[[shot]]\ntitle = \"a\"\nduration = 1\n";
                return t;
            }(), "[film] shot: the storyboard has 1001 shots: a film has at most 1000"},
        Bad{"long_title", "[[shot]]\nduration = 1\ntitle = \"" + std::string(kMaxStoryboardText + 1, 'x') + "\"\n",
            "shot 1, key 'title': \"xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx... (501 characters)\" is not allowed: a text has "
            "at most 500 characters"},
        Bad{"many_captions", ok_shot + "captions = [" + [] {
                std::string c;
                for (std::size_t i = 0; i <= kMaxShotCaptions; ++i) c += "{text = \"a\"},";
                return c;
            }() + "]\n", "key 'captions': has 21 captions: a shot has at most 20"}),
    [](const auto& info) { return std::string(info.param.name); });

// The bench geometry set directly in a shot (or a split's pane), no scenario file needed; an
// empty label means no annotation, not the scenario in words; [film] lang sets the film's words.
TEST(Storyboard, BenchGeometryLabelsAndLanguage) {
    const Storyboard b = parse(R"(
[film]
lang = "zh"
[[shot]]
from = 0
to = 10
rate = 5
width = 0.25
head_length = 3.0
body_length = 2.0
hole_offset = 0.25
bench_count = 100
label = ""
[[shot]]
duration = 4
split = [{ width = 0.28 }, { body_length = 2.4, label = "龙身 2.4 m" }]
)");
    EXPECT_EQ(b.film.language, Language::zh);
    const BenchSpec& bench = b.shots[0].views[0].scenario.bench;
    EXPECT_EQ(bench.width, 0.25);
    EXPECT_EQ(bench.head_length, 3.0);
    EXPECT_EQ(bench.body_length, 2.0);
    EXPECT_EQ(bench.hole_offset, 0.25);
    EXPECT_EQ(bench.bench_count, 100);
    ASSERT_TRUE(b.shots[0].views[0].label);
    EXPECT_EQ(*b.shots[0].views[0].label, "");
    EXPECT_EQ(b.shots[1].views[0].scenario.bench.width, 0.28);
    EXPECT_EQ(b.shots[1].views[0].scenario.bench.body_length, BenchSpec{}.body_length);
    EXPECT_EQ(b.shots[1].views[1].scenario.bench.body_length, 2.4);
    EXPECT_EQ(*b.shots[1].views[1].label, "龙身 2.4 m");
    // Drawn: the empty label leaves no annotation; the Chinese film's clock and legend in Chinese.
    const Film film(b);
    const Scene s = film.scene_at(0, 0);
    EXPECT_EQ(s.annotation, "");
    EXPECT_EQ(s.language, Language::zh);
    EXPECT_EQ(film.scene_at(1, 0, 1).annotation, "龙身 2.4 m");
}

TEST(Storyboard, ScenarioFilesAreFoundBesideTheStoryboard) {
    const Storyboard b = parse(ok_shot + "scenario = \"assets/cumcm2024.toml\"\nspeed = 2\n");
    EXPECT_EQ(b.shots[0].views[0].scenario.head_speed, 2.0);
    EXPECT_EQ(b.shots[0].views[0].scenario.path.pitch, 0.55);
}

}  // namespace

// A shot's scenario values are the key table's names, as in a scenario file; a scenario file in
// the old form is read with its warnings on the storyboard, once however many shots name it.
TEST(Storyboard, AnOldScenarioFilesWarningsComeBackOnce) {
    const std::string dir = dragon_test::scratch_dir().string();
    std::ofstream(dir + "/old-form.toml") << "[motion]\nhead_speed = 2\n[dragon]\nwidth = 0.25\n";
    const std::string story = "[film]\nscenario = \"old-form.toml\"\n"
                              "[[shot]]\nfrom = 10\nto = 11\nrate = 2\n"
                              "[[shot]]\nfrom = 11\nto = 12\nrate = 2\nbench_count = 50\nspeed = 3\n";
    const Storyboard b = parse_storyboard(story, "s.toml", dir, assets);
    ASSERT_EQ(b.shots.size(), 2u);
    EXPECT_EQ(b.shots[0].views[0].scenario.head_speed, 2.0);
    EXPECT_EQ(b.shots[0].views[0].scenario.bench.width, 0.25);
    EXPECT_EQ(b.shots[1].views[0].scenario.head_speed, 3.0);  // the shot's own key over the file
    EXPECT_EQ(b.shots[1].views[0].scenario.bench.bench_count, 50);
    ASSERT_EQ(b.warnings.size(), 2u);
    EXPECT_EQ(b.warnings[0].key, Key::width);  // [dragon] before [motion]
    EXPECT_EQ(b.warnings[1].key, Key::speed);
    EXPECT_NE(b.warnings[1].message.find("[motion] head_speed is an old name: write speed = 2"), std::string::npos);
    // Today's form: no warning.
    std::ofstream(dir + "/today-form.toml") << "speed = 2\nwidth = 0.25\n";
    EXPECT_TRUE(parse_storyboard("[film]\nscenario = \"today-form.toml\"\n[[shot]]\nfrom = 10\nto = 11\nrate = 2\n", "s.toml",
                                 dir, assets).warnings.empty());
}
