// Writing an output file all-or-nothing: write to a temporary file beside the target, then
// rename over it. An error (or a kill) leaves either the old file or nothing at the target;
// remove_live_temp_files() lets a signal handler clear the temporary files a kill interrupts.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "dragon/errors.hpp"

namespace dragon {

class AtomicFile {
public:
    // Creates the (empty) temporary file now, so a bad path fails before any work: throws
    // InputError naming the target and why (a folder, a missing folder, no permission, a
    // file system that refuses it).
    explicit AtomicFile(std::string target);
    ~AtomicFile();  // removes the temporary file unless commit() succeeded; never throws
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    // Where to write: a unique temporary path in the target's folder, same extension.
    const std::string& temp_path() const { return temp_; }
    const std::string& target() const { return target_; }
    // Renames the temporary file over the target. Throws std::runtime_error on failure.
    void commit();
    // The error for a failed write: "cannot write '<target>': <reason>". It names the target,
    // never the hidden temporary file the user did not choose.
    FileError write_error(const std::string& reason) const;

private:
    friend void commit_together(const std::vector<AtomicFile*>& files);
    std::string target_;
    std::string temp_;
    bool committed_ = false;
    int live_slot_ = -1;  // where temp_ is registered for remove_live_temp_files()
};

// Commits several files as one: every target ends up new or, if a rename fails, every target
// as it was (those already renamed are put back from hard links to the old files, made first).
// Throws std::runtime_error naming the target that failed.
void commit_together(const std::vector<AtomicFile*>& files);

// Removes the temporary file of every AtomicFile not yet committed or destroyed. Only
// async-signal-safe calls (no allocation, no locks): made for a handler of SIGINT, SIGTERM or
// SIGHUP that then ends the process. A file can be half renamed into place only by rename()
// itself, which is atomic, so the target is never touched.
void remove_live_temp_files() noexcept;

// Lower-case extension of a path including the dot (".png"), or "" if none.
std::string extension_of(const std::string& path);

}  // namespace dragon
