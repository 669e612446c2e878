#include "kill_cleanup.hpp"

#include <signal.h>

#include "dragon/atomic_file.hpp"

namespace dragon::cli {

namespace {

extern "C" void remove_temp_files_and_die(int sig) {
    remove_live_temp_files();
    // SA_RESETHAND restored the default action and the signal is blocked while we run: raised
    // again, it ends the process as soon as the handler returns, with the status a shell or a
    // parent expects from that signal.
    ::raise(sig);
}

}  // namespace

void install_kill_cleanup() {
    for (const int sig : {SIGINT, SIGTERM, SIGHUP}) {
        struct sigaction old {};
        if (::sigaction(sig, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) continue;
        struct sigaction act {};
        act.sa_handler = remove_temp_files_and_die;
        sigemptyset(&act.sa_mask);
        // Block the other two while cleaning, so a second signal cannot cut the cleanup short.
        for (const int other : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&act.sa_mask, other);
        act.sa_flags = SA_RESETHAND;
        ::sigaction(sig, &act, nullptr);
    }
}

}  // namespace dragon::cli
