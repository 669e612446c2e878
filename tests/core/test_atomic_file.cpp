// AtomicFile: a bad target fails at once, naming the target and why; commit_together makes a
// set of files all new or all old.
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "dragon/atomic_file.hpp"
#include "dragon/scenario.hpp"
#include "support/scratch.hpp"

namespace fs = std::filesystem;
using namespace dragon;

namespace {

std::string read(const fs::path& p) {
    std::ifstream f(p);
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

void write(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

// Names in the folder other than these: the temporary and backup files left behind.
std::vector<std::string> hidden_files(const fs::path& dir) {
    std::vector<std::string> out;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.path().filename().string().front() == '.') out.push_back(e.path().filename().string());
    return out;
}

std::string refusal(const std::string& target) {
    try {
        AtomicFile f(target);
    } catch (const InputError& e) {
        return e.what();
    }
    return "accepted";
}

}  // namespace

TEST(AtomicFile, MakesItsTemporaryFileAtOnce) {
    const fs::path dir = dragon_test::scratch_dir();
    {
        AtomicFile f((dir / "a.csv").string());
        EXPECT_TRUE(fs::exists(f.temp_path()));  // a target that cannot be written fails here, not later
        EXPECT_EQ(fs::path(f.temp_path()).parent_path(), dir);
        EXPECT_EQ(fs::path(f.temp_path()).extension(), ".csv");
    }
    EXPECT_TRUE(hidden_files(dir).empty());
    EXPECT_FALSE(fs::exists(dir / "a.csv"));
}

TEST(AtomicFile, BadTargetsNameTheTargetAndWhy) {
    const fs::path dir = dragon_test::scratch_dir();
    EXPECT_EQ(refusal(dir.string()), "output path '" + dir.string() + "' is a folder: give a file name");
    // /proc looks like a writable folder to root, but no file can be made in it.
    const std::string proc = refusal("/proc/x.csv");
    EXPECT_EQ(proc.rfind("output path '/proc/x.csv' is not writable: ", 0), 0u) << proc;
    EXPECT_EQ(proc.find(".tmp"), std::string::npos) << proc;  // never the hidden name
    EXPECT_NE(refusal("/no-such-folder/x.csv").find("folder '/no-such-folder' does not exist"), std::string::npos);
}

TEST(AtomicFile, WriteErrorsNameTheTarget) {
    const fs::path dir = dragon_test::scratch_dir();
    AtomicFile f((dir / "b.json").string());
    EXPECT_EQ(std::string(f.write_error("No space left on device").what()),
              "cannot write '" + (dir / "b.json").string() + "': No space left on device");
}

TEST(AtomicFile, CommitTogetherReplacesEveryFile) {
    const fs::path dir = dragon_test::scratch_dir();
    write((dir / "one.txt").string(), "old one");
    fs::remove(dir / "two.txt");
    std::vector<std::unique_ptr<AtomicFile>> files;
    for (const char* name : {"one.txt", "two.txt"}) {
        files.push_back(std::make_unique<AtomicFile>((dir / name).string()));
        write(files.back()->temp_path(), std::string("new ") + name);
    }
    commit_together({files[0].get(), files[1].get()});
    EXPECT_EQ(read(dir / "one.txt"), "new one.txt");
    EXPECT_EQ(read(dir / "two.txt"), "new two.txt");
    files.clear();
    EXPECT_TRUE(hidden_files(dir).empty());
}

TEST(AtomicFile, CommitTogetherPutsBackTheOldFilesWhenOneFails) {
    const fs::path dir = dragon_test::scratch_dir();
    for (const char* name : {"first.txt", "second.txt"}) write((dir / name).string(), std::string("old ") + name);
    fs::remove_all(dir / "third.txt");
    std::vector<std::unique_ptr<AtomicFile>> files;
    for (const char* name : {"first.txt", "second.txt", "third.txt"}) {
        files.push_back(std::make_unique<AtomicFile>((dir / name).string()));
        write(files.back()->temp_path(), std::string("new ") + name);
    }
    // The last target turns into a folder after the checks: its rename fails after the first two
    // have been replaced.
    fs::create_directory(dir / "third.txt");
    std::string what;
    try {
        commit_together({files[0].get(), files[1].get(), files[2].get()});
    } catch (const std::runtime_error& e) {
        what = e.what();
    }
    EXPECT_EQ(what.rfind("cannot write '" + (dir / "third.txt").string() + "': ", 0), 0u) << what;
    EXPECT_EQ(read(dir / "first.txt"), "old first.txt");
    EXPECT_EQ(read(dir / "second.txt"), "old second.txt");
    EXPECT_TRUE(fs::is_directory(dir / "third.txt"));
    files.clear();
    EXPECT_TRUE(hidden_files(dir).empty());
}

TEST(AtomicFile, CommitTogetherRemovesNewFilesThatHadNoOldOne) {
    const fs::path dir = dragon_test::scratch_dir();
    fs::remove(dir / "fresh.txt");
    fs::remove_all(dir / "blocked.txt");
    AtomicFile fresh((dir / "fresh.txt").string()), blocked((dir / "blocked.txt").string());
    write(fresh.temp_path(), "new");
    write(blocked.temp_path(), "new");
    fs::create_directory(dir / "blocked.txt");
    EXPECT_THROW(commit_together({&fresh, &blocked}), std::runtime_error);
    EXPECT_FALSE(fs::exists(dir / "fresh.txt"));  // as before: no file
}
