// Writing an output file all-or-nothing: write to a temporary file beside the target, then
// rename over it. An error (or a kill) leaves either the old file or nothing at the target;
// remove_live_temp_files() lets a signal handler clear the temporary files a kill interrupts.
//
// A target that is a symbolic link is written through: the file it points to is replaced and
// the link stays. A replaced file keeps its mode (never wider); a new one gets what the umask
// leaves of 0666, and the temporary file is readable by its owner alone while it is written. A
// read-only target is refused, as cp would refuse it.
//
// A RunOutputs makes a run's outputs one: given a RunOutputs, files are put in place only when
// the run commits it, all together, so that a run that fails (an error after a file was done, a
// full stdout at the end) leaves no new output; and no output may be one of the files the run
// reads (through InputFile given the same RunOutputs: a scenario, a sweep file, a storyboard and
// the files it names). The caller makes it and passes it to each writer and reader of the run;
// none is open behind its back, and several may be open at once (one per thread's run).
//
// The io component: the core builds with none of this (no file system).
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "dragon/errors.hpp"

namespace dragon {

class RunOutputs;

// One output file, written to a temporary file beside it and put in place by commit().
class AtomicFile {
public:
    // Creates the (empty) temporary file now, so a bad path fails before any work: throws
    // InputError naming the target and why (a folder, a missing folder, no permission, a
    // file system that refuses it, a read-only file, a link to nothing, not a regular file,
    // an input of the run `outputs`). Given a RunOutputs, commit() hands the file to it; null:
    // commit() puts it in place at once.
    explicit AtomicFile(std::string target, RunOutputs* outputs = nullptr);
    ~AtomicFile();  // removes the temporary file unless commit() succeeded; never throws
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    // Where to write: a unique temporary path in the target's folder, same extension.
    const std::string& temp_path() const { return temp_; }
    const std::string& target() const { return target_; }  // the path asked for
    // Renames the temporary file over the target (or hands it to its RunOutputs, which will).
    // Throws FileError on failure.
    void commit();
    // The error for a failed write: "cannot write '<target>': <reason>". It names the target,
    // never the hidden temporary file the user did not choose.
    FileError write_error(const std::string& reason) const;

private:
    friend void commit_together(const std::vector<AtomicFile*>& files);
    std::string target_;  // as given: messages name it
    std::string place_;   // where the file goes: the target, or the file its link points to
    std::string temp_;
    RunOutputs* outputs_ = nullptr;  // the run it belongs to, if any
    unsigned new_mode_ = 0644;  // a new file's mode: 0666 less the umask
    bool committed_ = false;
    int live_slot_ = -1;  // where temp_ is registered for remove_live_temp_files()
};

// One run's outputs, held until it succeeds (see above). Independent of any other RunOutputs
// open in the process. Thread-safe: files may be committed from any thread.
class RunOutputs {
public:
    RunOutputs();
    // Removes every file held and not committed (a sweep's unfinished rows stay); never throws.
    ~RunOutputs();
    RunOutputs(const RunOutputs&) = delete;
    RunOutputs& operator=(const RunOutputs&) = delete;
    // Puts every file held in place, all or none; throws FileError naming the one that failed.
    // The run stays open: files handed to it afterwards wait for the next commit().
    void commit();

    /// What the run holds and reads: defined and used by the io component's file code only.
    struct Files;
    Files& files() { return *files_; }  ///< the run's files (the io component's own use)

private:
    std::unique_ptr<Files> files_;
};

// Commits several files as one: every target ends up new or, if a rename fails, every target
// as it was (those already renamed are put back from hard links to the old files, made first).
// Throws FileError naming the target that failed. (Files given a RunOutputs are held with their
// run's other files instead.)
void commit_together(const std::vector<AtomicFile*>& files);

// Writes `text` into the temporary file of `out` (the caller commits it); throws FileError
// naming the target when the write fails.
void write_text_file(AtomicFile& out, const std::string& text);

// Makes the folder `dir` and its missing parents for a run's outputs, and says whether it is
// there now (false: it cannot be made). Given a RunOutputs, the folders it made are removed
// again when the run fails, if they are still empty: a failed run leaves no new folder either.
bool make_output_folder(const std::string& dir, RunOutputs* outputs = nullptr);

// Removes the temporary file of every AtomicFile not yet committed or destroyed. Only
// async-signal-safe calls (no allocation, no locks): made for a handler of SIGINT, SIGTERM or
// SIGHUP that then ends the process. A file can be half renamed into place only by rename()
// itself, which is atomic, so the target is never touched.
void remove_live_temp_files() noexcept;

// Lower-case extension of a path including the dot (".png"), or "" if none.
std::string extension_of(const std::string& path);

}  // namespace dragon
