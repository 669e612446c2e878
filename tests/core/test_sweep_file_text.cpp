// A sweep file's text parsed with no file behind it: the scenario it names is taken relative to
// the origin's folder, as std::filesystem would join them (the core joins the text itself, having
// no file system).
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "dragon/sweep.hpp"

using namespace dragon;

TEST(SweepFileText, TheScenarioIsBesideTheOrigin) {
    for (const std::string origin : {"map.toml", "maps/map.toml", "/srv/maps/map.toml", "/map.toml", "a/b/c/map.toml"}) {
        for (const std::string name : {"base.toml", "sub/base.toml", "/etc/base.toml", "../base.toml"}) {
            const SweepFile f = parse_sweep_file("scenario = \"" + name + "\"\n", origin);
            const std::filesystem::path n(name);
            const std::string expected =
                n.is_absolute() ? name : (std::filesystem::path(origin).parent_path() / n).string();
            EXPECT_EQ(f.scenario, expected) << origin << " + " << name;
        }
    }
}

TEST(SweepFileText, MistakesNameTheOrigin) {
    try {
        parse_sweep_file("colour = \"red\"\n", "there.toml");
        ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("sweep file 'there.toml': unknown key 'colour'"), std::string::npos)
            << e.what();
    }
}
