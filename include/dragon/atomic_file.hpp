// Writing an output file all-or-nothing: write to a temporary file beside the target, then
// rename over it. An error (or a kill) leaves either the old file or nothing at the target;
// remove_live_temp_files() lets a signal handler clear the temporary files a kill interrupts.
#pragma once

#include <string>

namespace dragon {

class AtomicFile {
public:
    // Checks the target's folder is writable now, so a bad path fails before any work.
    // Throws InputError naming the path if not.
    explicit AtomicFile(std::string target);
    ~AtomicFile();  // removes the temporary file unless commit() succeeded; never throws
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    // Where to write: a unique temporary path in the target's folder, same extension.
    const std::string& temp_path() const { return temp_; }
    const std::string& target() const { return target_; }
    // Renames the temporary file over the target. Throws std::runtime_error on failure.
    void commit();

private:
    std::string target_;
    std::string temp_;
    bool committed_ = false;
    int live_slot_ = -1;  // where temp_ is registered for remove_live_temp_files()
};

// Removes the temporary file of every AtomicFile not yet committed or destroyed. Only
// async-signal-safe calls (no allocation, no locks): made for a handler of SIGINT, SIGTERM or
// SIGHUP that then ends the process. A file can be half renamed into place only by rename()
// itself, which is atomic, so the target is never touched.
void remove_live_temp_files() noexcept;

// Lower-case extension of a path including the dot (".png"), or "" if none.
std::string extension_of(const std::string& path);

}  // namespace dragon
