// AtomicFile: a bad target fails at once, naming the target and why; commit_together makes a
// set of files all new or all old.
#include <grp.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "dragon/atomic_file.hpp"
#include "dragon/input_files.hpp"
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

std::string refusal(const std::string& target, RunOutputs* run = nullptr) {
    try {
        AtomicFile f(target, run);
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

namespace {

std::string fmt_mode(mode_t mode) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "mode %04o", static_cast<unsigned>(mode & 07777));
    return buf;
}

mode_t mode_of(const fs::path& p) {
    struct stat st {};
    return ::stat(p.c_str(), &st) == 0 ? st.st_mode & 07777 : 0;
}

void write_through(const std::string& target, const std::string& text, RunOutputs* run = nullptr) {
    AtomicFile f(target, run);
    write(f.temp_path(), text);
    f.commit();
}

// Runs `body` as an unprivileged user: in a child that gives up root for nobody (65534) when
// the tests run as root, as they do in CI; directly otherwise. Its result: "" or what failed.
std::string as_unprivileged(const std::function<std::string()>& body) {
    if (::geteuid() != 0) return body();
    int pipe_fds[2];
    if (::pipe(pipe_fds) != 0) return "no pipe";
    const pid_t pid = ::fork();
    if (pid == 0) {
        ::close(pipe_fds[0]);
        std::string result = "cannot become nobody";
        if (::setgroups(0, nullptr) == 0 && ::setgid(65534) == 0 && ::setuid(65534) == 0) result = body();
        if (!result.empty()) (void)!::write(pipe_fds[1], result.data(), result.size());
        ::_exit(0);
    }
    ::close(pipe_fds[1]);
    std::string result;
    char buf[256];
    for (ssize_t n; (n = ::read(pipe_fds[0], buf, sizeof buf)) > 0;) result.append(buf, static_cast<std::size_t>(n));
    ::close(pipe_fds[0]);
    int status = 0;
    ::waitpid(pid, &status, 0);
    return result;
}

// A folder anyone may write in, for the unprivileged runs.
fs::path open_dir(const std::string& name) {
    const fs::path dir = dragon_test::scratch_dir() / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    fs::permissions(dir, fs::perms::all);
    return dir;
}

}  // namespace

TEST(AtomicFile, AReplacedFileKeepsItsModeAndANewOneFollowsTheUmask) {
    const fs::path dir = dragon_test::scratch_dir();
    const fs::path secret = dir / "secret.csv";
    fs::remove(secret);
    write(secret.string(), "old");
    fs::permissions(secret, fs::perms::owner_read | fs::perms::owner_write);
    write_through(secret.string(), "new");
    EXPECT_EQ(read(secret), "new");
    EXPECT_EQ(mode_of(secret), 0600u);
    // While it is written, the temporary file is its owner's alone (it may replace a 0600 file).
    {
        AtomicFile f((dir / "pending.csv").string());
        EXPECT_EQ(mode_of(f.temp_path()), 0600u);
    }
    for (const mode_t mask : {mode_t{022}, mode_t{077}, mode_t{002}}) {
        const fs::path fresh = dir / "fresh.csv";
        fs::remove(fresh);
        const mode_t old = ::umask(mask);
        write_through(fresh.string(), "x");
        ::umask(old);
        EXPECT_EQ(mode_of(fresh), 0666u & ~mask) << std::oct << mask;
    }
}

TEST(AtomicFile, AReadOnlyTargetIsRefusedAndLeftAlone) {
    const fs::path dir = dragon_test::scratch_dir();
    const fs::path prot = dir / "prot.csv";
    fs::remove(prot);
    write(prot.string(), "keep me");
    fs::permissions(prot, fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
    // Refused by its mode bits, so even root (whom the system would let write) is refused.
    EXPECT_EQ(refusal(prot.string()), "output path '" + prot.string() + "' is read-only (mode 0444): make it writable "
                                      "(chmod u+w) or write another file");
    EXPECT_EQ(read(prot), "keep me");
    EXPECT_TRUE(hidden_files(dir).empty());
    fs::permissions(prot, fs::perms::owner_write, fs::perm_options::add);
    // Someone else's file in a folder anyone may write in: the folder would let the rename
    // through, the file's own permission does not.
    const fs::path shared = open_dir("shared");
    write((shared / "root.csv").string(), "root's");
    fs::permissions(shared / "root.csv", fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read |
                                             fs::perms::others_read);
    const std::string result = as_unprivileged([&] {
        const std::string why = refusal((shared / "root.csv").string());
        if (why.find("is read-only (mode 0644)") == std::string::npos) return "accepted or other: " + why;
        return std::string();
    });
    EXPECT_EQ(result, "");
    EXPECT_EQ(read(shared / "root.csv"), "root's");
}

TEST(AtomicFile, ALinkIsWrittenThroughAndStaysALink) {
    const fs::path dir = dragon_test::scratch_dir();
    fs::remove_all(dir / "real");
    fs::create_directories(dir / "real");
    const fs::path real = dir / "real" / "m.csv", link = dir / "link.csv", chain = dir / "chain.csv";
    write(real.string(), "old");
    fs::permissions(real, fs::perms::owner_read | fs::perms::owner_write);
    fs::remove(link), fs::remove(chain);
    fs::create_symlink(real, link);
    fs::create_symlink(link, chain);  // a link to a link
    {
        AtomicFile f(chain.string());
        // The temporary file beside the real file: the rename stays on its file system.
        EXPECT_EQ(fs::path(f.temp_path()).parent_path(), dir / "real");
        write(f.temp_path(), "new");
        f.commit();
    }
    EXPECT_TRUE(fs::is_symlink(chain));
    EXPECT_TRUE(fs::is_symlink(link));
    EXPECT_EQ(read(real), "new");
    EXPECT_EQ(mode_of(real), 0600u);
    // A link to nothing, and a link to something that is not a file, are refused.
    fs::remove(dir / "dangling.csv");
    fs::create_symlink(dir / "nowhere.csv", dir / "dangling.csv");
    EXPECT_EQ(refusal((dir / "dangling.csv").string()),
              "output path '" + (dir / "dangling.csv").string() + "' is a symbolic link to '" +
                  (dir / "nowhere.csv").string() + "', which does not exist: remove the link or make its file first");
    fs::remove(dir / "null.csv");
    fs::create_symlink("/dev/null", dir / "null.csv");
    EXPECT_EQ(refusal((dir / "null.csv").string()),
              "output path '" + (dir / "null.csv").string() + "' is a device: give the name of a regular file");
    EXPECT_TRUE(fs::exists("/dev/null") && !fs::is_regular_file("/dev/null"));
}

TEST(AtomicFile, AnotherOwnersFileKeepsItsOwnerOrGivesItsGroupNoMore) {
    const fs::path dir = open_dir("owners");
    const fs::path file = dir / "theirs.csv";
    write(file.string(), "old");
    if (::geteuid() == 0) {
        // Root keeps the owner and group of the file it replaces.
        ASSERT_EQ(::chown(file.c_str(), 65534, 65534), 0);
        fs::permissions(file, fs::perms::owner_all | fs::perms::group_read);
        write_through(file.string(), "new");
        struct stat st {};
        ASSERT_EQ(::stat(file.c_str(), &st), 0);
        EXPECT_EQ(st.st_uid, 65534u);
        EXPECT_EQ(st.st_gid, 65534u);
        EXPECT_EQ(st.st_mode & 0777, 0740u);
        ASSERT_EQ(::chown(file.c_str(), 0, 0), 0);
    }
    // Someone who cannot keep the old group: the new group may read no more than everyone may.
    fs::permissions(file, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read |
                              fs::perms::group_write | fs::perms::others_write);
    const std::string result = as_unprivileged([&] {
        if (::geteuid() != 0 && ::access(file.c_str(), W_OK) != 0) return std::string();  // cannot write it at all
        try {
            write_through(file.string(), "by nobody");
        } catch (const std::exception& e) {
            return std::string("refused: ") + e.what();
        }
        struct stat st {};
        if (::stat(file.c_str(), &st) != 0) return std::string("gone");
        if ((st.st_mode & 0777) != 0622) return fmt_mode(st.st_mode);
        return std::string();
    });
    EXPECT_EQ(result, "");
}

TEST(RunOutputs, FilesArePutInPlaceOnlyWhenTheRunCommits) {
    const fs::path dir = dragon_test::scratch_dir();
    fs::remove(dir / "kept.csv"), fs::remove(dir / "fresh.csv");
    write((dir / "kept.csv").string(), "old");
    {
        RunOutputs run;
        write_through((dir / "kept.csv").string(), "new", &run);
        write_through((dir / "fresh.csv").string(), "new", &run);
        EXPECT_EQ(read(dir / "kept.csv"), "old");  // held
        EXPECT_FALSE(fs::exists(dir / "fresh.csv"));
    }  // the run failed: nothing new
    EXPECT_EQ(read(dir / "kept.csv"), "old");
    EXPECT_FALSE(fs::exists(dir / "fresh.csv"));
    EXPECT_TRUE(hidden_files(dir).empty());
    {
        RunOutputs run;
        write_through((dir / "kept.csv").string(), "new", &run);
        write_through((dir / "fresh.csv").string(), "new", &run);
        // A file given no run is put in place at once, a run open or not.
        fs::remove(dir / "alone.csv");
        write_through((dir / "alone.csv").string(), "at once");
        EXPECT_EQ(read(dir / "alone.csv"), "at once");
        EXPECT_FALSE(fs::exists(dir / "fresh.csv"));
        run.commit();
    }
    EXPECT_EQ(read(dir / "kept.csv"), "new");
    EXPECT_EQ(read(dir / "fresh.csv"), "new");
    EXPECT_TRUE(hidden_files(dir).empty());
}

TEST(RunOutputs, NoOutputIsAnInputOfTheRun) {
    const fs::path dir = dragon_test::scratch_dir();
    const fs::path sc = dir / "sc.csv", link = dir / "sc-link.csv";
    write(sc.string(), "width = 0.3\n");
    fs::remove(link);
    fs::create_symlink(sc, link);
    {
        RunOutputs run;
        load_scenario(sc.string(), {}, &run);
        // Through any name of the same file: a link, or the path itself.
        for (const fs::path& p : {sc, link}) {
            const std::string why = refusal(p.string(), &run);
            EXPECT_EQ(why, "output path '" + p.string() + "' is the scenario file '" + sc.string() +
                               "' this run reads: give the output another name, so that the input is not lost");
        }
    }
    {
        RunOutputs run;
        AtomicFile out(link.string(), &run);  // the output first, then the input: refused when read
        try {
            load_scenario(sc.string(), {}, &run);
            ADD_FAILURE() << "read";
        } catch (const InputError& e) {
            EXPECT_EQ(std::string(e.what()), "the scenario file '" + sc.string() + "' is also the output '" +
                                                 link.string() + "': give the output another name, so that the input "
                                                                 "is not lost");
        }
    }
    // Another run knows nothing of this one's inputs.
    {
        RunOutputs run, other;
        load_scenario(sc.string(), {}, &run);
        EXPECT_EQ(refusal(sc.string(), &other), "accepted");
    }
    // Outside a run, a program may read a file and write it later.
    load_scenario(sc.string());
    EXPECT_EQ(refusal(sc.string()), "accepted");
    EXPECT_EQ(read(sc), "width = 0.3\n");
}

TEST(RunOutputs, FilesCommittedFromSeveralThreadsArePlacedTogether) {
    const fs::path dir = dragon_test::scratch_dir() / "threads";
    fs::remove_all(dir);
    fs::create_directories(dir);
    {
        RunOutputs run;
        std::vector<std::thread> writers;
        for (int t = 0; t < 4; ++t)
            writers.emplace_back([&, t] {
                for (int k = 0; k < 8; ++k) {
                    char name[32];
                    std::snprintf(name, sizeof name, "f%d-%d.csv", t, k);
                    write_through((dir / name).string(), "x", &run);
                }
            });
        for (std::thread& w : writers) w.join();
        EXPECT_EQ(hidden_files(dir).size(), 32u);  // all held, none in place
        run.commit();
    }
    EXPECT_TRUE(hidden_files(dir).empty());
    int placed = 0;
    for (const auto& e : fs::directory_iterator(dir)) placed += read(e.path()) == "x";
    EXPECT_EQ(placed, 32);
}

// Two runs open at once, each on its own thread (two Python calls, say): each holds its own
// files, and one that fails takes only its own with it.
TEST(RunOutputs, TwoRunsOnTwoThreadsKeepTheirFilesApart) {
    const fs::path dir = dragon_test::scratch_dir() / "two_runs";
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::atomic<int> opened{0};
    // Each run waits for the other to be open before it writes, so that both are open at once.
    const auto both_open = [&] {
        ++opened;
        while (opened.load() < 2) std::this_thread::yield();
    };
    std::thread committed([&] {
        RunOutputs run;
        both_open();
        for (int k = 0; k < 5; ++k) write_through((dir / ("kept" + std::to_string(k) + ".csv")).string(), "a", &run);
        ASSERT_TRUE(make_output_folder((dir / "kept_folder").string(), &run));
        run.commit();
    });
    std::thread failed([&] {
        RunOutputs run;
        both_open();
        for (int k = 0; k < 5; ++k) write_through((dir / ("lost" + std::to_string(k) + ".csv")).string(), "b", &run);
        ASSERT_TRUE(make_output_folder((dir / "lost_folder" / "inner").string(), &run));
    });  // never committed: as a run that failed
    committed.join();
    failed.join();
    for (int k = 0; k < 5; ++k) {
        EXPECT_EQ(read(dir / ("kept" + std::to_string(k) + ".csv")), "a") << k;
        EXPECT_FALSE(fs::exists(dir / ("lost" + std::to_string(k) + ".csv"))) << k;
    }
    EXPECT_TRUE(fs::is_directory(dir / "kept_folder"));
    EXPECT_FALSE(fs::exists(dir / "lost_folder"));
    EXPECT_TRUE(hidden_files(dir).empty());
}

TEST(AtomicFile, AFileThatCannotBeWrittenIsAFileError) {
    const fs::path dir = dragon_test::scratch_dir() / "vanishing";
    fs::create_directories(dir);
    const std::string target = (dir / "t.csv").string();
    AtomicFile out(target);
    std::ofstream(out.temp_path()) << "t,handle,x,y,speed\n";
    fs::remove_all(dir);  // the folder goes away before the rename
    try {
        out.commit();
        ADD_FAILURE() << "committed";
    } catch (const FileError& e) {
        EXPECT_EQ(e.path(), target);
        EXPECT_FALSE(e.reason().empty());
    }
}
