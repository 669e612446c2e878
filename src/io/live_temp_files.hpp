// The temporary files live AtomicFiles own, kept where a signal handler can reach them: a kill
// between creating a temporary file and renaming it would otherwise leave it behind.
//
// The registry is a fixed table of fixed-size slots (no allocation, no locks), each guarded by a
// lock-free atomic state, so that remove_live_temp_files() is async-signal-safe.
#pragma once

#include <string>

namespace dragon::live_temp {

// Records a path; returns its slot, or -1 when the table is full or the path too long (the file
// then still works, it is only not removed on a kill).
int add(const std::string& path) noexcept;
// Forgets a slot from add() (-1 is ignored). Call it after the file is renamed or removed.
void drop(int slot) noexcept;

}  // namespace dragon::live_temp
