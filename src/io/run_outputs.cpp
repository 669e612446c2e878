#include "run_outputs.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <memory>
#include <mutex>
#include <vector>

#include <fmt/format.h>

#include "live_temp_files.hpp"
#include "dragon/atomic_file.hpp"
#include "dragon/input_file.hpp"

namespace dragon {

namespace {

struct Held {
    placement::Placement file;
    int slot = -1;  // the source's entry for a kill's cleanup (temporary files only)
};

struct Input {
    dev_t dev;
    ino_t ino;
    std::string what, path;
};

struct Output {
    std::string target, place;
};

}  // namespace

// One run's files. One mutex per run: its files are committed and read from any thread, rarely;
// two runs share nothing.
struct RunOutputs::Files {
    std::mutex lock;
    std::vector<Held> held;
    std::vector<std::string> folders;  // made by the run, outermost first
    std::vector<Input> inputs;
    std::vector<Output> outputs;
};

namespace {

std::string input_words(const Input& in) { return fmt::format("the {} '{}'", in.what, shown_text(in.path, 4096)); }

}  // namespace

bool run_outputs::hold(RunOutputs* run, const placement::Placement& p, int live_slot) {
    if (!run) return false;
    RunOutputs::Files& f = run->files();
    const std::lock_guard<std::mutex> lock(f.lock);
    f.held.push_back({p, live_slot});
    return true;
}

void run_outputs::note_input(RunOutputs* run, dev_t dev, ino_t ino, const std::string& what,
                             const std::string& path) {
    if (!run) return;
    RunOutputs::Files& f = run->files();
    const std::lock_guard<std::mutex> lock(f.lock);
    const Input in{dev, ino, what, path};
    for (const Output& out : f.outputs) {
        struct stat st {};
        if (::stat(out.place.c_str(), &st) == 0 && st.st_dev == dev && st.st_ino == ino)
            throw InputError(fmt::format("{} is also the output '{}': give the output another name, so that the "
                                         "input is not lost", input_words(in), shown_text(out.target, 4096)));
    }
    f.inputs.push_back(in);
}

void run_outputs::note_output(RunOutputs* run, const std::string& target, const std::string& place) {
    if (!run) return;
    RunOutputs::Files& f = run->files();
    const std::lock_guard<std::mutex> lock(f.lock);
    struct stat st {};
    if (::stat(place.c_str(), &st) == 0)
        for (const Input& in : f.inputs)
            if (st.st_dev == in.dev && st.st_ino == in.ino)
                throw InputError(fmt::format("output path '{}' is {} this run reads: give the output another name, "
                                             "so that the input is not lost", shown_text(target, 4096),
                                             input_words(in)));
    f.outputs.push_back({target, place});
}

void run_outputs::note_folders(RunOutputs* run, const std::vector<std::string>& made) {
    if (!run) return;
    RunOutputs::Files& f = run->files();
    const std::lock_guard<std::mutex> lock(f.lock);
    f.folders.insert(f.folders.end(), made.begin(), made.end());
}

RunOutputs::RunOutputs() : files_(std::make_unique<Files>()) {}

RunOutputs::~RunOutputs() {
    for (const Held& h : files_->held) {
        if (!h.file.keep_source) ::unlink(h.file.source.c_str());
        live_temp::drop(h.slot);
    }
    // Innermost first; a folder that holds anything (the user's, or a kept file) stays.
    for (auto f = files_->folders.rbegin(); f != files_->folders.rend(); ++f) ::rmdir(f->c_str());
}

void RunOutputs::commit() {
    std::vector<placement::Placement> files;
    {
        const std::lock_guard<std::mutex> lock(files_->lock);
        for (const Held& h : files_->held) files.push_back(h.file);
    }
    placement::place_all(files);
    const std::lock_guard<std::mutex> lock(files_->lock);
    // In place: nothing left to remove, and nothing for a kill to clean up.
    for (const Held& h : files_->held) live_temp::drop(h.slot);
    files_->held.clear();
    files_->folders.clear();
}

bool make_output_folder(const std::string& dir, RunOutputs* outputs) {
    namespace fs = std::filesystem;
    std::error_code ec;
    // The missing ones, outermost first.
    std::vector<std::string> missing;
    for (fs::path p = fs::path(dir); !p.empty() && !fs::exists(fs::symlink_status(p, ec)); p = p.parent_path()) {
        missing.insert(missing.begin(), p.string());
        if (p == p.parent_path()) break;
    }
    std::vector<std::string> made;
    for (const std::string& m : missing) {
        if (::mkdir(m.c_str(), 0777) != 0) break;  // the umask applies, as to any folder
        made.push_back(m);
    }
    run_outputs::note_folders(outputs, made);
    return fs::is_directory(dir, ec);
}

}  // namespace dragon
