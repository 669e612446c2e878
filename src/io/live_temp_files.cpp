#include "live_temp_files.hpp"

#include <unistd.h>

#include <atomic>
#include <cstring>

#include "dragon/atomic_file.hpp"

namespace dragon {

namespace {

// A handful of outputs are written at once at most (figures: one file at a time; a video: one);
// 64 leaves room for a library user writing many in parallel.
constexpr int kSlots = 64;
constexpr std::size_t kPathBytes = 4096;  // PATH_MAX on Linux

enum State : int { kFree, kFilling, kLive };

struct Slot {
    std::atomic<int> state{kFree};
    char path[kPathBytes];
};

// A signal handler may only touch lock-free atomics.
static_assert(std::atomic<int>::is_always_lock_free);

Slot slots[kSlots];

}  // namespace

int live_temp::add(const std::string& path) noexcept {
    if (path.size() >= kPathBytes) return -1;
    for (int k = 0; k < kSlots; ++k) {
        int expected = kFree;
        // kFilling keeps the handler off the slot while its path is half written.
        if (!slots[k].state.compare_exchange_strong(expected, kFilling)) continue;
        std::memcpy(slots[k].path, path.c_str(), path.size() + 1);
        slots[k].state.store(kLive);
        return k;
    }
    return -1;
}

void live_temp::drop(int slot) noexcept {
    if (slot >= 0 && slot < kSlots) slots[slot].state.store(kFree);
}

void remove_live_temp_files() noexcept {
    for (Slot& s : slots)
        if (s.state.load() == kLive) ::unlink(s.path);  // unlink is async-signal-safe
}

}  // namespace dragon
