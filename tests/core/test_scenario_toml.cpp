// A scenario file's one vocabulary: flat keys named as the key table names them. The old form
// (sections [dragon], [path], [motion]; kind, head_speed) reads to the same scenario with one
// warning per old name, a key in both forms is refused naming both, an unknown key's message
// lists the table's names, and a scenario written by scenario_toml reads back digit for digit.
#include <random>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "dragon/scenario.hpp"
#include "support/scratch.hpp"

using namespace dragon;

namespace {

// Every value of two scenarios, compared exactly.
void expect_same(const Scenario& a, const Scenario& b) {
    EXPECT_EQ(a.bench.bench_count, b.bench.bench_count);
    EXPECT_EQ(a.bench.head_length, b.bench.head_length);
    EXPECT_EQ(a.bench.body_length, b.bench.body_length);
    EXPECT_EQ(a.bench.width, b.bench.width);
    EXPECT_EQ(a.bench.hole_offset, b.bench.hole_offset);
    EXPECT_EQ(a.path.kind, b.path.kind);
    EXPECT_EQ(a.path.pitch, b.path.pitch);
    EXPECT_EQ(a.path.start_turn, b.path.start_turn);
    EXPECT_EQ(a.path.turn_radius, b.path.turn_radius);
    EXPECT_EQ(a.path.turn_pitch, b.path.turn_pitch);
    EXPECT_EQ(a.path.arc_ratio, b.path.arc_ratio);
    EXPECT_EQ(a.head_speed, b.head_speed);
}

// The InputError parse_scenario_toml throws for `text` (its message empty if it accepts).
InputError refusal(const std::string& text) {
    try {
        parse_scenario_toml(text, "x.toml");
    } catch (const InputError& e) {
        return e;
    }
    return InputError("");
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// No value is the contest's, so that a key read into the wrong place shows.
const char* const kOld = R"([dragon]
bench_count = 101
head_length = 3.1
body_length = 1.9
width = 0.27
hole_offset = 0.25

[path]
kind = "turnaround"
pitch = 0.61
start_turn = 12.5
turn_radius = 4.2
turn_pitch = 1.6
arc_ratio = 1.5

[motion]
head_speed = 1.25
)";

const char* const kNew = R"(bench_count = 101
head_length = 3.1
body_length = 1.9
width = 0.27
hole_offset = 0.25
path = "turnaround"
pitch = 0.61
start_turn = 12.5
turn_radius = 4.2
turn_pitch = 1.6
arc_ratio = 1.5
speed = 1.25
)";

}  // namespace

TEST(ScenarioToml, TheNewFormReadsToTheSameScenarioAsTheOld) {
    const LoadedScenario old_form = parse_scenario_toml(kOld, "old.toml");
    const LoadedScenario new_form = parse_scenario_toml(kNew, "new.toml");
    expect_same(new_form.scenario, old_form.scenario);
    EXPECT_EQ(new_form.values, value::all);
    EXPECT_EQ(old_form.values, value::all);
    EXPECT_EQ(new_form.scenario.path.kind, PathKind::turnaround);
    EXPECT_EQ(new_form.scenario.bench.bench_count, 101);
    EXPECT_EQ(new_form.scenario.head_speed, 1.25);
    EXPECT_TRUE(new_form.warnings.empty());
    EXPECT_EQ(old_form.warnings.size(), old_scenario_names().size());  // one per old name, no more
}

TEST(ScenarioToml, EachOldNameGivesOneWarningNamingItsKey) {
    for (const OldScenarioName& o : old_scenario_names()) {
        const std::string value = o.key == Key::path ? "\"turnaround\"" : o.key == Key::bench_count ? "77" : "0.875";
        const std::string name(key_info(o.key).name);
        const LoadedScenario old_form =
            parse_scenario_toml(fmt::format("[{}]\n{} = {}\n", o.section, o.name, value), "legacy.toml");
        const LoadedScenario new_form = parse_scenario_toml(fmt::format("{} = {}\n", name, value), "today.toml");
        expect_same(old_form.scenario, new_form.scenario);
        EXPECT_EQ(old_form.values, new_form.values) << name;
        EXPECT_NE(new_form.values == 0, o.key != Key::path) << name;  // the path kind is no value bit
        ASSERT_EQ(old_form.warnings.size(), 1u) << o.name;
        const KeyWarning& w = old_form.warnings[0];
        EXPECT_EQ(w.key, o.key);
        EXPECT_EQ(w.old_name, fmt::format("[{}] {}", o.section, o.name));
        EXPECT_EQ(w.message, fmt::format("scenario file 'legacy.toml': [{}] {} is an old name: write {} = {} at the "
                                         "top level", o.section, o.name, name, value));
        EXPECT_TRUE(new_form.warnings.empty());
    }
    // The two renamed keys, by name: the flags' --speed and --path.
    const LoadedScenario speed = parse_scenario_toml("[motion]\nhead_speed = 2.5\n", "s.toml");
    EXPECT_EQ(speed.scenario.head_speed, 2.5);
    ASSERT_EQ(speed.warnings.size(), 1u);
    EXPECT_EQ(speed.warnings[0].key, Key::speed);
    EXPECT_TRUE(has(speed.warnings[0].message, "write speed = 2.5 at the top level"));
    const LoadedScenario kind = parse_scenario_toml("[path]\nkind = \"turnaround\"\n", "k.toml");
    ASSERT_EQ(kind.warnings.size(), 1u);
    EXPECT_TRUE(has(kind.warnings[0].message, "[path] kind is an old name: write path = \"turnaround\""));
}

TEST(ScenarioToml, AKeyInBothFormsIsRefusedNamingBoth) {
    for (const OldScenarioName& o : old_scenario_names()) {
        const std::string value = o.key == Key::path ? "\"spiral\"" : o.key == Key::bench_count ? "50" : "0.5";
        const std::string name(key_info(o.key).name);
        const InputError e = refusal(fmt::format("{} = {}\n[{}]\n{} = {}\n", name, value, o.section, o.name, value));
        EXPECT_EQ(e.key(), o.key) << e.what();
        // TOML itself refuses the key path beside a table [path]: that is said in our words.
        const std::string both = o.section == "path" && o.key == Key::path
                                     ? "path and the old section [path] cannot both be in one file"
                                     : fmt::format("{} and [{}] {} both set", name, o.section, o.name);
        EXPECT_TRUE(has(e.what(), both)) << e.what();
    }
    const InputError path_beside_its_section = refusal("path = \"turnaround\"\n[path]\npitch = 0.6\n");
    EXPECT_EQ(path_beside_its_section.key(), Key::path);
    EXPECT_TRUE(has(path_beside_its_section.what(), "write [path]'s keys at the top level"))
        << path_beside_its_section.what();
    // Other malformed TOML is said as the parser says it.
    EXPECT_TRUE(has(refusal("pitch = \n").what(), "is not valid TOML (line 1")) << refusal("pitch = \n").what();
    // Two different keys, one in each form, are no conflict.
    const LoadedScenario mixed = parse_scenario_toml("pitch = 0.7\n[motion]\nhead_speed = 2\n", "m.toml");
    EXPECT_EQ(mixed.scenario.path.pitch, 0.7);
    EXPECT_EQ(mixed.scenario.head_speed, 2.0);
    EXPECT_EQ(mixed.warnings.size(), 1u);
}

TEST(ScenarioToml, AnUnknownKeyIsRefusedListingTheKeyTablesNames) {
    for (const std::string text : {"widht = 0.3\n", "[dragon]\nwidht = 0.3\n", "[motion]\nspeed = 1\n",
                                   "head_speed = 1\n", "bench-count = 5\n", "zoom = 2\n"}) {
        const InputError e = refusal(text);
        EXPECT_TRUE(has(e.what(), "unknown key")) << text << e.what();
        // Every key a scenario sets, named as the key table names it, and nothing else.
        for (const KeyInfo& k : all_keys()) {
            if (k.key == Key::none) continue;
            const bool listed = k.scenario != 0 || k.key == Key::path;
            if (listed) {
                EXPECT_TRUE(has(e.what(), std::string(k.name))) << k.name << ": " << e.what();
            }
        }
        EXPECT_FALSE(has(e.what(), "font_pt")) << e.what();
    }
    EXPECT_TRUE(has(refusal("[dragons]\nwidth = 0.3\n").what(), "unknown section [dragons]"));
}

TEST(ScenarioToml, AValueOfTheWrongKindCarriesItsKey) {
    struct Case {
        const char* text;
        Key key;
    };
    for (const Case& c : {Case{"width = \"wide\"\n", Key::width}, Case{"bench_count = 2.5\n", Key::bench_count},
                          Case{"bench_count = 0\n", Key::bench_count}, Case{"path = \"circle\"\n", Key::path},
                          Case{"[path]\nkind = 3\n", Key::path}, Case{"[motion]\nhead_speed = true\n", Key::speed}}) {
        const InputError e = refusal(c.text);
        EXPECT_EQ(e.key(), c.key) << c.text << e.what();
        EXPECT_TRUE(has(e.what(), "scenario file 'x.toml': ")) << e.what();
        EXPECT_FALSE(e.value().empty()) << e.what();
    }
}

TEST(ScenarioToml, AWrittenScenarioReadsBackDigitForDigit) {
    std::mt19937 rng(20240928);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < 200; ++i) {
        Scenario s;
        s.bench.bench_count = 1 + static_cast<int>(u(rng) * 500);
        s.bench.head_length = 1 + 4 * u(rng);
        s.bench.body_length = 1 + 3 * u(rng);
        s.bench.width = 0.1 + u(rng) / 3;
        s.bench.hole_offset = u(rng) / 3;
        s.path.kind = i % 2 ? PathKind::turnaround : PathKind::spiral;
        s.path.pitch = 0.3 + u(rng);
        s.path.start_turn = 1 + 30 * u(rng);
        s.path.turn_radius = 1 + 9 * u(rng);
        s.path.turn_pitch = 0.5 + 2 * u(rng);
        s.path.arc_ratio = i == 7 ? 1e-5 : 0.2 + 4 * u(rng);  // an exponent, as TOML reads it
        s.head_speed = i == 9 ? 3.0 : 3 * u(rng);             // a whole number, as TOML reads it
        const std::string text = scenario_toml(s);
        const LoadedScenario back = parse_scenario_toml(text, "saved.toml");
        expect_same(back.scenario, s);
        EXPECT_EQ(back.values, value::all) << text;
        EXPECT_TRUE(back.warnings.empty()) << text;
    }
}

TEST(ScenarioToml, TheContestFileIsTheDefaultsInTodaysForm) {
    const std::string path = std::string(DRAGON_SOURCE_DIR) + "/assets/cumcm2024.toml";
    const LoadedScenario contest = parse_scenario_toml(dragon_test::slurp(path), path);
    expect_same(contest.scenario, Scenario{});
    EXPECT_EQ(contest.values, value::all);
    EXPECT_TRUE(contest.warnings.empty());
}

TEST(ScenarioToml, ThePagesSavedFormReadsBack) {
    // As docs/explorer.html's "Save TOML" writes it (web/src/app.js scenarioToml): the path, then
    // every value in the page's order, numbers as JavaScript prints them.
    const LoadedScenario page = parse_scenario_toml(
        "# A scenario saved by docs/explorer.html: dragon <command> --scenario this.toml\npath = \"turnaround\"\n"
        "bench_count = 120\nhead_length = 3.41\nbody_length = 2.2\nwidth = 0.3\nhole_offset = 0.275\nspeed = 1.5\n"
        "pitch = 0.55\nstart_turn = 16\nturn_radius = 4.5\nturn_pitch = 1.7\narc_ratio = 2\n",
        "scenario.toml");
    Scenario want;
    want.bench.bench_count = 120;
    want.head_speed = 1.5;
    want.path.kind = PathKind::turnaround;
    expect_same(page.scenario, want);
    EXPECT_TRUE(page.warnings.empty());
}
