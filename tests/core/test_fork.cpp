// A process that forks after using the library (Python's ProcessPoolExecutor, a server's
// workers) gets a child that can use it again: the library keeps no pool of its own, so the
// child inherits no bookkeeping of threads it does not have. The child's answers are checked
// against the parent's, and the parent gives up on a child that hangs instead of hanging too.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <thread>

#include "dragon/analyses.hpp"
#include "dragon/executor.hpp"

using namespace dragon;

namespace {

// Runs `child` in a forked process and returns its exit status: 0 when it returned true, 1
// when false, -1 (after killing it) when it ran longer than `limit`.
template <class F>
int in_forked_child(F child, std::chrono::seconds limit) {
    const pid_t pid = ::fork();
    if (pid == 0) ::_exit(child() ? 0 : 1);  // no gtest, no atexit handlers in the child
    if (pid < 0) return -2;
    const auto give_up = std::chrono::steady_clock::now() + limit;
    int status = 0;
    while (::waitpid(pid, &status, WNOHANG) == 0) {
        if (std::chrono::steady_clock::now() > give_up) {
            ::kill(pid, SIGKILL);
            ::waitpid(pid, &status, 0);
            return -1;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : -3;
}

bool same_contact(const CollideAnswer& a, const CollideAnswer& b) {
    return a.contact && b.contact && a.contact->travel == b.contact->travel && a.contact->bench_a == b.contact->bench_a &&
           a.contact->bench_b == b.contact->bench_b;
}

}  // namespace

TEST(Fork, AChildSearchesAgainAfterItsParentSearchedInParallel) {
#if defined(__SANITIZE_THREAD__)
    GTEST_SKIP() << "ThreadSanitizer does not support starting threads in a child forked from a multi-threaded process";
#endif
    const Simulation sim(Scenario{});
    ThreadPool parent_pool(2);  // alive while the parent forks: its threads are not the child's
    const CollideAnswer parent = first_contact_of_motion(sim, &parent_pool);
    MinPitchOptions o;
    o.executor = &parent_pool;
    const MinPitch parent_pitch = min_pitch(Scenario{}, 0.44, 0.46, o);
    ASSERT_TRUE(parent.contact);

    // The child searches with no executor, and with a pool of its own.
    const int status = in_forked_child(
        [&] {
            const CollideAnswer alone = first_contact_of_motion(sim);
            ThreadPool child_pool(2);
            const CollideAnswer pooled = first_contact_of_motion(sim, &child_pool);
            MinPitchOptions co;
            co.executor = &child_pool;
            const MinPitch pitch = min_pitch(Scenario{}, 0.44, 0.46, co);
            return same_contact(alone, parent) && same_contact(pooled, parent) && pitch.pitch == parent_pitch.pitch;
        },
        std::chrono::seconds(120));
    EXPECT_NE(status, -1) << "the forked child hung";
    EXPECT_EQ(status, 0) << "the forked child's answers differ from its parent's";
    // And the parent's pool still works after the fork.
    EXPECT_TRUE(same_contact(first_contact_of_motion(sim, &parent_pool), parent));
}
