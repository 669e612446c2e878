// Files keep their protections, and a failed run writes nothing (issue 20, section 7); bounded
// workers (section 6). Modes are read from the files themselves: the tests run as root in CI,
// and root may write a 0444 file, so the refusal is checked by the mode bits the program reads,
// and what only an unprivileged user meets runs as nobody (setpriv), or is skipped saying why.
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <thread>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/cli_run.hpp"

namespace fs = std::filesystem;
using dragon_test::contains;
using dragon_test::count_lines;
using dragon_test::fresh_dir;
using dragon_test::run_dragon;
using dragon_test::slurp;

namespace {

unsigned mode_of(const fs::path& p) {
    struct stat st {};
    return ::stat(p.c_str(), &st) == 0 ? st.st_mode & 07777 : 0;
}

// Names in the folder, hidden ones (temporary files) included.
std::vector<std::string> names_in(const fs::path& dir) {
    std::vector<std::string> out;
    for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path().filename().string());
    std::sort(out.begin(), out.end());
    return out;
}

// A command writing each kind of file, to `file` in its folder.
struct Writer {
    std::string name, args;  // "@" stands for the target
};
const std::vector<Writer> kWriters = {
    {"render.png", "render --time 1 --size 64x64 -q -o @"},
    {"table.csv", "simulate --to 1 -q -o @"},
    {"table.xlsx", "simulate --to 1 -q -o @"},
    {"contact.json", "collide -q -o @"},
    {"film.gif", "video --to 1 --size 64x48 --fps 2 -q -o @"},
    {"rows.csv", "sweep --vary pitch=0.5,0.6 --measure collide -q -o @"},  // a sweep's rows, renamed into place
};

std::string with_target(std::string args, const fs::path& target) {
    args.replace(args.find('@'), 1, target.string());
    return args;
}

}  // namespace

TEST(FileProtections, AReplacedOutputKeepsItsMode) {
    const fs::path dir = fresh_dir("modes");
    for (const Writer& w : kWriters) {
        const fs::path target = dir / w.name;
        ASSERT_EQ(run_dragon(with_target(w.args, target)).code, 0) << w.name;
        for (const unsigned mode : {0600u, 0640u, 0604u}) {
            fs::permissions(target, static_cast<fs::perms>(mode));
            const auto r = run_dragon(with_target(w.args, target));
            ASSERT_EQ(r.code, 0) << w.name << "\n" << r.err;
            EXPECT_EQ(mode_of(target), mode) << w.name;
        }
    }
    for (const std::string& n : names_in(dir)) EXPECT_NE(n.front(), '.') << n;  // no temporary file left
    // A sweep's unfinished rows are no more readable than the file they will replace: a killed
    // run leaves them so.
    const fs::path rows = dir / "rows.csv";
    fs::permissions(rows, static_cast<fs::perms>(0600));
    const pid_t pid = dragon_test::spawn_dragon({"sweep", "--vary", "bench-count=60:130:15", "--vary", "arc-ratio=1.5,2",
                                                 "--measure", "turnaround", "--workers", "1", "-q", "-o", rows.string()});
    ASSERT_GT(pid, 0);
    for (int i = 0; i < 400 && !fs::exists(rows.string() + ".partial"); ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    EXPECT_EQ(mode_of(rows.string() + ".partial"), 0600u);
    ::kill(pid, SIGKILL);
    ::waitpid(pid, nullptr, 0);
    fs::remove(rows.string() + ".partial");
}

TEST(FileProtections, NewFilesFollowTheUmask) {
    const fs::path dir = fresh_dir("umask");
    for (const Writer& w : kWriters)
        for (const unsigned mask : {077u, 027u, 022u}) {
            const fs::path target = dir / w.name;
            fs::remove(target);
            char prefix[32];
            std::snprintf(prefix, sizeof prefix, "umask %03o;", mask);
            const auto r = run_dragon(with_target(w.args, target), prefix);
            ASSERT_EQ(r.code, 0) << w.name << "\n" << r.err;
            EXPECT_EQ(mode_of(target), 0666u & ~mask) << w.name << " under umask " << prefix;
        }
}

TEST(FileProtections, AReadOnlyTargetIsRefusedAsCpWouldRefuseIt) {
    const fs::path dir = fresh_dir("read-only");
    for (const Writer& w : kWriters) {
        const fs::path target = dir / w.name;
        std::ofstream(target) << "keep";
        fs::permissions(target, static_cast<fs::perms>(0444));
        const auto r = run_dragon(with_target(w.args, target));
        EXPECT_EQ(r.code, 2) << w.name << "\n" << r.err;
        EXPECT_EQ(count_lines(r.err), 1) << r.err;
        EXPECT_TRUE(contains(r.err, "output path '" + target.string() + "' is read-only (mode 0444)")) << r.err;
        EXPECT_EQ(slurp(target), "keep") << w.name;
        EXPECT_EQ(mode_of(target), 0444u);
    }
    EXPECT_EQ(names_in(dir).size(), kWriters.size());  // nothing else made
}

TEST(FileProtections, SomeoneElsesFileIsRefusedToAnUnprivilegedUser) {
    if (::geteuid() != 0) GTEST_SKIP() << "needs root to make a file of another owner and run dragon as nobody";
    if (std::system("setpriv --help >/dev/null 2>&1") != 0) GTEST_SKIP() << "no setpriv to run dragon as nobody";
    // A folder anyone may write in (so the rename would go through), and root's 0644 file in it:
    // its own permission does not let nobody write it.
    const fs::path dir = fresh_dir("shared");
    fs::permissions(dir, fs::perms::all);
    const fs::path target = dir / "root.csv";
    std::ofstream(target) << "root's";
    fs::permissions(target, static_cast<fs::perms>(0644));
    const auto r = run_dragon("simulate --to 1 -o " + target.string(), "setpriv --reuid=65534 --regid=65534 --clear-groups");
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_TRUE(contains(r.err, "output path '" + target.string() + "' is read-only (mode 0644)")) << r.err;
    EXPECT_EQ(slurp(target), "root's");
    // A 0600 file of nobody's own, replaced by nobody: still 0600.
    const fs::path own = dir / "own.png";
    const auto made = run_dragon("render --time 1 --size 64x64 -q -o " + own.string(),
                                 "umask 022; setpriv --reuid=65534 --regid=65534 --clear-groups");
    ASSERT_EQ(made.code, 0) << made.err;
    EXPECT_EQ(mode_of(own), 0644u);
    ASSERT_EQ(::chmod(own.c_str(), 0600), 0);
    const auto again = run_dragon("render --time 2 --size 64x64 -q -o " + own.string(),
                                  "setpriv --reuid=65534 --regid=65534 --clear-groups");
    ASSERT_EQ(again.code, 0) << again.err;
    EXPECT_EQ(mode_of(own), 0600u);
}

TEST(FileProtections, ALinkIsWrittenThroughAndStaysALink) {
    const fs::path dir = fresh_dir("links");
    fs::create_directories(dir / "real");
    for (const Writer& w : kWriters) {
        const fs::path real = dir / "real" / w.name, link = dir / ("link-" + w.name);
        std::ofstream(real) << "old";
        fs::permissions(real, static_cast<fs::perms>(0640));
        fs::create_symlink(real, link);
        const auto r = run_dragon(with_target(w.args, link));
        ASSERT_EQ(r.code, 0) << w.name << "\n" << r.err;
        EXPECT_TRUE(fs::is_symlink(link)) << w.name;
        EXPECT_EQ(fs::read_symlink(link), real);
        EXPECT_NE(slurp(real), "old") << w.name;
        EXPECT_EQ(mode_of(real), 0640u) << w.name;
    }
    for (const std::string& n : names_in(dir / "real")) EXPECT_NE(n.front(), '.') << n;
}

// A run that fails (here: its answers cannot reach stdout) leaves no new output, and an old
// file as it was.
TEST(FileProtections, AFailedRunWritesNothing) {
    const fs::path dir = fresh_dir("failed");
    struct Case {
        std::string name, args;
    };
    const std::vector<Case> cases = {
        {"film.gif", "video --to collision --size 64x48 --fps 1 --speedup 100 -o @"},
        {"contact.json", "collide -o @"},
        {"study.csv", "turnaround --no-clearance -o @"},
        {"rows.csv", "sweep --vary pitch=0.5,0.6 --measure collide --json -o @"},
    };
    for (const Case& c : cases) {
        const fs::path target = dir / c.name;
        fs::remove(target);
        auto r = run_dragon(with_target(c.args, target), "", "/dev/full");
        EXPECT_EQ(r.code, 1) << c.name << "\n" << r.err;
        EXPECT_TRUE(contains(r.err, "cannot write the answers to standard output")) << r.err;
        EXPECT_FALSE(contains(r.err, "wrote")) << r.err;  // nor says it wrote anything
        EXPECT_FALSE(fs::exists(target)) << c.name;
        // An old file stays as it was. (A sweep's unfinished rows are refused without --resume:
        // they go first.)
        fs::remove(target.string() + ".partial");
        std::ofstream(target) << "old";
        r = run_dragon(with_target(c.args, target), "", "/dev/full");
        EXPECT_EQ(r.code, 1) << c.name;
        EXPECT_EQ(slurp(target), "old") << c.name;
        fs::remove(target);
    }
    // The sweep's rows stay where --resume finds them; nothing else is left.
    std::vector<std::string> left = names_in(dir);
    EXPECT_EQ(left, std::vector<std::string>{"rows.csv.partial"});
    const auto folder = run_dragon("solve --only q1 -o " + (dir / "new" / "out").string(), "", "/dev/full");
    EXPECT_EQ(folder.code, 1);
    EXPECT_FALSE(fs::exists(dir / "new")) << "a failed run leaves no new folder either";
}

TEST(BoundedResources, SweepWorkersAreCappedAtTheScenariosAndTheCores) {
    const auto r = run_dragon("sweep --vary pitch=0.5,0.6 --measure collide --workers 100000");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(contains(r.err, "dragon: note: --workers 100000: 2 run at once (at most one per scenario, 2 here, and 4 "
                                "per core")) << r.err;
    EXPECT_EQ(count_lines(r.out), 4);  // the first line, the header and the two rows
    EXPECT_EQ(run_dragon("sweep --vary pitch=0.5,0.6 --measure collide --workers 100000 -q").err, "");
    EXPECT_EQ(run_dragon("sweep --vary pitch=0.5,0.6 --measure collide --workers 2").err.find("note"), std::string::npos);
}
