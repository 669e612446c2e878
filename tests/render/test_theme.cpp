#include <filesystem>
#include <fstream>

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

TEST(Theme, AssetFolderIsFoundWithoutAHint) {
    // The source tree (or an install) is found whatever the current directory is.
    EXPECT_NO_THROW(find_asset_dir());
    EXPECT_NO_THROW(load_theme("dark"));
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

}  // namespace
}  // namespace dragon
