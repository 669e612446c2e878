#include "run_outputs.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <mutex>
#include <stdexcept>
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

// The open run's files. One mutex: files are committed and read from any thread, rarely.
struct Run {
    std::vector<Held> held;
    std::vector<std::string> folders;  // made by the run, outermost first
    std::vector<Input> inputs;
    std::vector<Output> outputs;
};

std::mutex run_lock;
Run* open_run = nullptr;

std::string input_words(const Input& in) { return fmt::format("the {} '{}'", in.what, shown_text(in.path, 4096)); }

}  // namespace

bool run_outputs::hold(const placement::Placement& p, int live_slot) {
    const std::lock_guard<std::mutex> lock(run_lock);
    if (!open_run) return false;
    open_run->held.push_back({p, live_slot});
    return true;
}

void run_outputs::note_input(dev_t dev, ino_t ino, const std::string& what, const std::string& path) {
    const std::lock_guard<std::mutex> lock(run_lock);
    if (!open_run) return;
    const Input in{dev, ino, what, path};
    for (const Output& out : open_run->outputs) {
        struct stat st {};
        if (::stat(out.place.c_str(), &st) == 0 && st.st_dev == dev && st.st_ino == ino)
            throw InputError(fmt::format("{} is also the output '{}': give the output another name, so that the "
                                         "input is not lost", input_words(in), shown_text(out.target, 4096)));
    }
    open_run->inputs.push_back(in);
}

void run_outputs::note_output(const std::string& target, const std::string& place) {
    const std::lock_guard<std::mutex> lock(run_lock);
    if (!open_run) return;
    struct stat st {};
    if (::stat(place.c_str(), &st) == 0)
        for (const Input& in : open_run->inputs)
            if (st.st_dev == in.dev && st.st_ino == in.ino)
                throw InputError(fmt::format("output path '{}' is {} this run reads: give the output another name, "
                                             "so that the input is not lost", shown_text(target, 4096),
                                             input_words(in)));
    open_run->outputs.push_back({target, place});
}

RunOutputs::RunOutputs() {
    const std::lock_guard<std::mutex> lock(run_lock);
    if (open_run) throw std::logic_error("RunOutputs: a run is open already");
    open_run = new Run;
}

RunOutputs::~RunOutputs() {
    Run* run = nullptr;
    {
        const std::lock_guard<std::mutex> lock(run_lock);
        run = open_run;
        open_run = nullptr;
    }
    if (!run) return;
    for (const Held& h : run->held) {
        if (!h.file.keep_source) ::unlink(h.file.source.c_str());
        live_temp::drop(h.slot);
    }
    // Innermost first; a folder that holds anything (the user's, or a kept file) stays.
    for (auto f = run->folders.rbegin(); f != run->folders.rend(); ++f) ::rmdir(f->c_str());
    delete run;
}

void RunOutputs::commit() {
    std::vector<placement::Placement> files;
    {
        const std::lock_guard<std::mutex> lock(run_lock);
        if (!open_run) throw std::logic_error("RunOutputs::commit: no run is open");
        for (const Held& h : open_run->held) files.push_back(h.file);
    }
    placement::place_all(files);
    const std::lock_guard<std::mutex> lock(run_lock);
    // In place: nothing left to remove, and nothing for a kill to clean up.
    for (const Held& h : open_run->held) live_temp::drop(h.slot);
    open_run->held.clear();
    open_run->folders.clear();
}

bool make_output_folder(const std::string& dir) {
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
    {
        const std::lock_guard<std::mutex> lock(run_lock);
        if (open_run) open_run->folders.insert(open_run->folders.end(), made.begin(), made.end());
    }
    return fs::is_directory(dir, ec);
}

}  // namespace dragon
