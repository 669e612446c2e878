// Scenario files read from disk: the values the file sets are what its text sets (the core's
// parse_scenario_toml), and what is not a readable file (a folder) is named as such.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "dragon/input_files.hpp"
#include "support/scratch.hpp"

namespace fs = std::filesystem;
using namespace dragon;

TEST(ScenarioFile, ReadsWhatItsTextSays) {
    const std::string text = "[dragon]\nwidth = 0.25\nbench_count = 5\n[path]\npitch = 0.1\n";
    const fs::path path = dragon_test::scratch_dir() / "some.toml";
    std::ofstream(path) << text;
    Scenario base;
    base.head_speed = 1.5;  // kept: the file does not set it
    const LoadedScenario read = read_scenario_file(path.string(), base);
    const LoadedScenario parsed = parse_scenario_toml(text, path.string(), base);
    EXPECT_EQ(read.values, parsed.values);
    EXPECT_EQ(read.scenario.bench.width, 0.25);
    EXPECT_EQ(read.scenario.bench.bench_count, 5);
    EXPECT_EQ(read.scenario.head_speed, 1.5);
    EXPECT_EQ(load_scenario(path.string(), base).path.pitch, 0.1);
}

TEST(ScenarioFile, AFolderIsNamed) {
    const std::string folder = dragon_test::scratch_dir().string();
    try {
        read_scenario_file(folder);
        ADD_FAILURE() << "a folder was read";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), "scenario file '" + folder + "' is a folder: give a .toml file");
    }
}
