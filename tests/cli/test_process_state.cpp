// The library leaves the process it runs in as it found it: a solve (its workbooks included), a
// picture and a film start no thread that outlives them, open no descriptor they keep, never
// point file descriptor 2 elsewhere (not even for a moment, watched from another thread while
// they run) and change no environment variable. And no source defines a C function: the library
// and the tool take no symbol of libc or of another library for themselves. Here rather than in
// tests/core: it runs every layer and reads the sources of all of them.
#include <dlfcn.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "dragon/contest.hpp"
#include "dragon/film.hpp"
#include "dragon/render.hpp"
#include "dragon/still.hpp"
#include "dragon/tables.hpp"
#include "support/scratch.hpp"

extern char** environ;

namespace fs = std::filesystem;
using namespace dragon;

namespace {

// The threads of this process, from the kernel's count.
int thread_count() {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
        if (line.rfind("Threads:", 0) == 0) return std::stoi(line.substr(8));
    return -1;
}

std::set<std::string> open_descriptors() {
    std::set<std::string> out;
    for (const auto& e : fs::directory_iterator("/proc/self/fd")) out.insert(e.path().filename().string());
    return out;
}

std::vector<std::string> environment() {
    std::vector<std::string> out;
    for (char** e = environ; *e; ++e) out.emplace_back(*e);
    return out;
}

struct FileId {
    dev_t dev = 0;
    ino_t ino = 0;
    bool operator==(const FileId&) const = default;
};

FileId stderr_file() {
    struct stat st {};
    ::fstat(STDERR_FILENO, &st);
    return {st.st_dev, st.st_ino};
}

// Runs `work` on a thread of its own while this thread watches file descriptor 2; true when
// fd 2 named another file at any moment of it.
template <class F>
bool stderr_moved_during(F work) {
    const FileId before = stderr_file();
    std::atomic<bool> done{false};
    std::exception_ptr failure;
    std::thread worker([&] {
        try {
            work();
        } catch (...) {
            failure = std::current_exception();
        }
        done = true;
    });
    bool moved = false;
    while (!done) moved = moved || !(stderr_file() == before);
    worker.join();
    if (failure) std::rethrow_exception(failure);
    return moved || !(stderr_file() == before);
}

void expect_left_as_found(const char* what, const std::function<void()>& work) {
    const int threads = thread_count();
    const std::set<std::string> fds = open_descriptors();
    const std::vector<std::string> env = environment();
    EXPECT_FALSE(stderr_moved_during(work)) << what << ": file descriptor 2 was pointed elsewhere";
    EXPECT_EQ(thread_count(), threads) << what << ": threads left running";
    EXPECT_EQ(open_descriptors(), fds) << what << ": descriptors left open";
    EXPECT_EQ(environment(), env) << what << ": the environment changed";
}

}  // namespace

TEST(ProcessState, ASolveAPictureAndAFilmLeaveTheProcessAsTheyFoundIt) {
    const fs::path dir = dragon_test::fresh_dir("process_state");
    expect_left_as_found("solve", [&] {
        ThreadPool pool(2);
        ContestOptions o;
        o.executor = &pool;
        const ContestAnswers a = solve_contest(Scenario{}, o);
        write_result_xlsx(a.q1->frames, (dir / "result1.xlsx").string());
        write_result2_xlsx(a.q2->contact->frame, (dir / "result2.xlsx").string());
    });
    expect_left_as_found("render", [&] {
        const Simulation sim(Scenario{});
        const Still still = still_at(sim, 300.0, SceneOptions{});
        render_png(still.scene, 320, 320, (dir / "moment.png").string());
        render_pdf(still.scene, 320, 320, (dir / "moment.pdf").string());
    });
    expect_left_as_found("film", [&] {
        const Storyboard board = parse_storyboard("[film]\nsize = \"64x48\"\nfps = 4\n[[shot]]\nfrom = 0\nto = 2\nrate = 1\n",
                                                  "inline", dir.string(), DRAGON_SOURCE_DIR "/assets");
        ThreadPool pool(2);
        VideoOptions vo;
        vo.width = 64, vo.height = 48, vo.fps = 4;
        vo.executor = &pool;
        write_film(Film(board), (dir / "film.mp4").string(), vo);
    });
    EXPECT_TRUE(fs::file_size(dir / "result1.xlsx") > 0);
    EXPECT_TRUE(fs::file_size(dir / "film.mp4") > 0);
}

TEST(ProcessState, NoSourceDefinesAFunctionOfAnotherLibrary) {
    // extern "C" with a function body whose name another library has (libc's gmtime, minizip's
    // zipOpenNewFileInZip4_64): a definition that would take it for the whole process. A C
    // function of our own name (the tool's signal handler) is no one else's.
    const std::regex definition(R"(extern\s+"C"[^;{(]*?([A-Za-z_][A-Za-z_0-9]*)\s*\([^;{]*\)[^;{]*\{)");
    const auto anothers = [](const std::string& name) {
        if (name == "gmtime" || name.rfind("zip", 0) == 0 || name.rfind("lxw_", 0) == 0) return true;
        void* symbol = ::dlsym(RTLD_DEFAULT, name.c_str());
        Dl_info where{};
        // Defined in a shared library this process loaded, not in the test program itself.
        return symbol && ::dladdr(symbol, &where) && where.dli_fname &&
               std::string(where.dli_fname).find(".so") != std::string::npos;
    };
    std::vector<std::string> found;
    for (const char* top : {"src", "python/src", "include"})
        for (const auto& e : fs::recursive_directory_iterator(fs::path(DRAGON_SOURCE_DIR) / top)) {
            if (!e.is_regular_file()) continue;
            const std::string s = dragon_test::slurp(e.path());
            for (auto it = std::sregex_iterator(s.begin(), s.end(), definition); it != std::sregex_iterator(); ++it)
                if (anothers((*it)[1])) found.push_back(e.path().string() + ": " + (*it)[1].str());
        }
    EXPECT_TRUE(found.empty()) << "functions of other libraries defined in: " << ::testing::PrintToString(found);
}
