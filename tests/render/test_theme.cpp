#include <filesystem>
#include <fstream>

#include <stdlib.h>

#include <gtest/gtest.h>

#include "dragon/render.hpp"
#include "dragon/scenario.hpp"

namespace dragon {
namespace {

const std::string assets = std::string(DRAGON_SOURCE_DIR) + "/assets";

TEST(Theme, LightAndDarkLoadFromTheAssetFolder) {
    const Theme light = load_theme("light", assets);
    const Theme dark = load_theme("dark", assets);
    EXPECT_EQ(light.name, "light");
    EXPECT_EQ(dark.name, "dark");
    // A dark theme is dark: its background is darker than its text, the light one the reverse.
    auto lum = [](Rgba c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; };
    EXPECT_GT(lum(light.background), lum(light.text));
    EXPECT_LT(lum(dark.background), lum(dark.text));
    EXPECT_GE(dark.speed_ramp.size(), 2u);
}

TEST(Theme, TheAssetFolderIsTheCallersNotTheEnvironments) {
    EXPECT_EQ(find_asset_dir(assets), assets);
    EXPECT_EQ(load_theme("dark", assets).background.r, load_theme(assets + "/themes/dark.toml").background.r);
    // $DRAGON_ASSETS is the dragon tool's to read, not the library's: set to the assets here, it
    // is not where a call without a folder looks (the install tree, absent in a build tree).
    ::setenv("DRAGON_ASSETS", assets.c_str(), 1);
    std::string found;
    try {
        found = find_asset_dir();
    } catch (const FileError& e) {
        EXPECT_EQ(std::string(e.what()).find(assets), std::string::npos) << e.what();
    }
    ::unsetenv("DRAGON_ASSETS");
    EXPECT_NE(found, assets);
}

TEST(Theme, UnknownNameIsAnInputError) {
    EXPECT_THROW(load_theme("sepia", assets), InputError);
    EXPECT_THROW(load_theme("/no/such/theme.toml", assets), InputError);
}

TEST(Theme, FileOverridesSomeColoursAndRejectsBadOnes) {
    const std::filesystem::path dir = std::filesystem::path(DRAGON_TEST_TMP) / "themes";
    std::filesystem::create_directories(dir);
    {
        std::ofstream(dir / "mine.toml") << "name = \"mine\"\n[colours]\nhead = \"#00ff0080\"\n";
        const Theme t = load_theme((dir / "mine.toml").string());
        EXPECT_EQ(t.name, "mine");
        EXPECT_DOUBLE_EQ(t.head.g, 1.0);
        EXPECT_NEAR(t.head.a, 128 / 255.0, 1e-12);
        EXPECT_DOUBLE_EQ(t.body.r, Theme{}.body.r);  // untouched keys keep the defaults
    }
    std::ofstream(dir / "bad.toml") << "[colours]\nhead = \"red\"\n";
    EXPECT_THROW(load_theme((dir / "bad.toml").string()), InputError);
    std::ofstream(dir / "typo.toml") << "[colours]\nheda = \"#ff0000\"\n";
    EXPECT_THROW(load_theme((dir / "typo.toml").string()), InputError);
    std::ofstream(dir / "broken.toml") << "[colours\n";
    EXPECT_THROW(load_theme((dir / "broken.toml").string()), InputError);
}

std::string refusal(const std::string& path) {
    try {
        load_theme(path, assets);
    } catch (const InputError& e) {
        return e.what();
    }
    return "accepted";
}

TEST(Theme, OnlyTheKeysOfAThemeAreTaken) {
    const std::filesystem::path dir = std::filesystem::path(DRAGON_TEST_TMP) / "themes";
    std::filesystem::create_directories(dir);
    const auto file = [&](const std::string& name, const std::string& text) {
        std::ofstream(dir / name) << text;
        return (dir / name).string();
    };
    const std::string where = "theme file '" + dir.string() + "/";
    EXPECT_EQ(refusal(file("bogus.toml", "bogus = 1\n")),
              where + "bogus.toml': unknown key 'bogus' (allowed: name, font and the [colours] table)");
    EXPECT_EQ(refusal(file("typo.toml", "[colour]\nhead = \"#ff0000\"\n")),
              where + "typo.toml': unknown section [colour] (allowed: [colours])");
    // A storyboard is no theme.
    EXPECT_EQ(refusal(file("story.toml", "[film]\nfps = 5\n[[shot]]\ntitle = \"a\"\nduration = 1\n")),
              where + "story.toml': unknown section [film] (allowed: [colours])");
    EXPECT_EQ(refusal(file("font.toml", "font = \"No Such Font Anywhere\"\n")),
              where + "font.toml': font \"No Such Font Anywhere\" is not installed (fc-list lists the fonts there are)");
    EXPECT_EQ(refusal(file("name.toml", "name = 3\n")), where + "name.toml': name must be a string");
    // Tables 10,000 deep: refused by their first name, or by the parser's depth limit.
    std::string deep = "[";
    for (int i = 0; i < 10000; ++i) deep += i ? ".a" : "a";
    EXPECT_EQ(refusal(file("deep.toml", deep + "]\n")), where + "deep.toml': unknown section [a] (allowed: [colours])");
    std::string nested = "colours = ";
    for (int i = 0; i < 10000; ++i) nested += "{a = ";
    nested += "1" + std::string(10000, '}') + "\n";
    EXPECT_NE(refusal(file("nested.toml", nested)).find("nested.toml' is not valid TOML"), std::string::npos);
    // Generic families and installed fonts are taken.
    EXPECT_EQ(load_theme(file("sans.toml", "font = \"sans-serif\"\n")).font, "sans-serif");
    EXPECT_EQ(load_theme(file("dejavu.toml", "font = \"DejaVu Sans\"\n")).font, "DejaVu Sans");
}

TEST(Theme, OnlyARegularFileIsReadAsATheme) {
    EXPECT_EQ(refusal("/dev/zero"), "theme file '/dev/zero' is a device: only a regular file is read");
    const std::filesystem::path dir = std::filesystem::path(DRAGON_TEST_TMP) / "themes";
    std::filesystem::create_directories(dir);
    EXPECT_EQ(refusal((dir / "none.toml").string()), "theme file '" + (dir / "none.toml").string() + "' does not exist");
}

}  // namespace
}  // namespace dragon
