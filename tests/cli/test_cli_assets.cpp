// The tool finds its assets (themes) beside itself, in share/benchdragon next to its bin
// folder, with no path into the source tree built in: run with $DRAGON_ASSETS unset, from the
// build tree and from a prefix it was copied into; without them it says what it looked for.
#include <gtest/gtest.h>

#include <filesystem>

#include "support/cli_run.hpp"
#include "support/scratch.hpp"

namespace fs = std::filesystem;
using dragon_test::contains;

namespace {

dragon_test::CliRun run_exe(const fs::path& exe, const std::string& args) {
    const fs::path dir = dragon_test::scratch_dir();
    const fs::path out = dir / "stdout.txt", err = dir / "stderr.txt";
    const std::string cmd = "env -u DRAGON_ASSETS " + exe.string() + " " + args + " >" + out.string() + " 2>" + err.string();
    const int status = std::system(cmd.c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, dragon_test::slurp(out), dragon_test::slurp(err)};
}

}  // namespace

TEST(Assets, TheToolFindsItsCopyInTheBuildTree) {
    const fs::path png = dragon_test::scratch_dir() / "dark.png";
    fs::remove(png);
    const auto r = run_exe(DRAGON_EXE, "render --time 10 --theme dark --size 64x64 -q -o " + png.string());
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(fs::exists(png));
}

TEST(Assets, AnInstalledCopyFindsTheInstalledAssets) {
    const fs::path prefix = dragon_test::scratch_dir() / "prefix";
    fs::remove_all(prefix);
    fs::create_directories(prefix / "bin");
    fs::copy_file(DRAGON_EXE, prefix / "bin" / "dragon");
    fs::permissions(prefix / "bin" / "dragon", fs::perms::owner_all);
    const fs::path png = dragon_test::scratch_dir() / "installed.png";
    fs::remove(png);
    // No share/benchdragon yet: one line saying where it looked, no picture.
    const auto bare = run_exe(prefix / "bin" / "dragon", "render --time 10 --theme dark --size 64x64 -q -o " + png.string());
    EXPECT_NE(bare.code, 0);
    EXPECT_TRUE(contains(bare.err, "DRAGON_ASSETS")) << bare.err;
    EXPECT_EQ(dragon_test::count_lines(bare.err), 1) << bare.err;
    EXPECT_FALSE(fs::exists(png));
    fs::create_directories(prefix / "share");
    fs::copy(fs::path(DRAGON_SOURCE_DIR) / "assets", prefix / "share" / "benchdragon", fs::copy_options::recursive);
    const auto r = run_exe(prefix / "bin" / "dragon", "render --time 10 --theme dark --size 64x64 -q -o " + png.string());
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(fs::exists(png));
}
