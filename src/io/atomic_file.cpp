#include "dragon/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include <fmt/format.h>

#include "file_placement.hpp"
#include "live_temp_files.hpp"
#include "run_outputs.hpp"
#include "dragon/input_file.hpp"

namespace dragon {

namespace fs = std::filesystem;

std::string extension_of(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

AtomicFile::AtomicFile(std::string target, RunOutputs* outputs) : target_(std::move(target)), outputs_(outputs) {
    if (target_.empty()) throw InputError("output path is empty: give a file name");
    const std::string shown = shown_text(target_, 4096);
    place_ = placement::resolve_target(target_);
    fs::path dir = fs::path(place_).parent_path();
    if (dir.empty()) dir = ".";
    std::error_code ec;
    if (!fs::is_directory(dir, ec))
        throw InputError(fmt::format("output path '{}' is not writable: folder '{}' does not exist", shown,
                                     shown_text(dir.string(), 4096)));
    if (::access(dir.c_str(), W_OK) != 0)
        throw InputError(fmt::format("output path '{}' is not writable: no permission to write in '{}'", shown,
                                     shown_text(dir.string(), 4096)));
    run_outputs::note_output(outputs_, target_, place_);
    temp_ = placement::hidden_name(place_, "tmp");
    // Registered before the file exists, so a kill at any later moment finds it.
    live_slot_ = live_temp::add(temp_);
    // Created now: a folder that looks writable but is not (/proc, a read-only mount) fails
    // here, before any work, and not halfway through writing.
    const int fd = ::open(temp_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0) {
        const int err = errno;
        live_temp::drop(live_slot_);
        throw InputError(fmt::format("output path '{}' is not writable: no file can be made in '{}' ({})", shown,
                                     shown_text(dir.string(), 4096), std::strerror(err)));
    }
    // Made with 0666, the umask took its part: what is left is a new file's mode. While it is
    // written, its owner alone may read it (it may replace a file others may not read).
    struct stat st {};
    if (::fstat(fd, &st) == 0) new_mode_ = st.st_mode & 0777;
    ::fchmod(fd, 0600);
    ::close(fd);
}

AtomicFile::~AtomicFile() {
    if (!committed_) {
        std::error_code ec;
        fs::remove(temp_, ec);
    }
    live_temp::drop(live_slot_);
}

namespace {

placement::Placement placement_of(const std::string& temp, const std::string& place, const std::string& target,
                                  unsigned new_mode) {
    return {temp, place, target, static_cast<mode_t>(new_mode), false};
}

}  // namespace

void AtomicFile::commit() {
    const placement::Placement p = placement_of(temp_, place_, target_, new_mode_);
    if (run_outputs::hold(outputs_, p, live_slot_)) {
        // The run owns the temporary file now, and its entry for a kill's cleanup.
        committed_ = true;
        live_slot_ = -1;
        return;
    }
    placement::place_all({p});
    committed_ = true;
    // A kill between the rename and here only unlinks a name that no longer exists.
    live_temp::drop(live_slot_);
    live_slot_ = -1;
}

FileError AtomicFile::write_error(const std::string& reason) const { return FileError(target_, "write", reason); }

void commit_together(const std::vector<AtomicFile*>& files) {
    // A file given a run goes with that run's files; the others are placed together now.
    std::vector<placement::Placement> now;
    std::vector<AtomicFile*> placed;
    for (AtomicFile* f : files) {
        if (!f->outputs_) {
            now.push_back(placement_of(f->temp_, f->place_, f->target_, f->new_mode_));
            placed.push_back(f);
        }
    }
    placement::place_all(now);
    for (AtomicFile* f : placed) {
        f->committed_ = true;
        live_temp::drop(f->live_slot_);
        f->live_slot_ = -1;
    }
    for (AtomicFile* f : files) {
        if (!f->outputs_) continue;
        run_outputs::hold(f->outputs_, placement_of(f->temp_, f->place_, f->target_, f->new_mode_), f->live_slot_);
        f->committed_ = true;
        f->live_slot_ = -1;
    }
}

void write_text_file(AtomicFile& out, const std::string& text) {
    errno = 0;
    std::FILE* f = std::fopen(out.temp_path().c_str(), "wb");
    if (!f) throw out.write_error(std::strerror(errno));
    const bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
    const int err = errno;
    if (std::fclose(f) != 0 || !ok) throw out.write_error(std::strerror(ok ? errno : err));
}

}  // namespace dragon
