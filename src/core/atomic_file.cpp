#include "dragon/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include <fmt/format.h>

#include "core/live_temp_files.hpp"
#include "dragon/scenario.hpp"

namespace dragon {

namespace fs = std::filesystem;

std::string extension_of(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

namespace {

// A hidden name beside the target, unique per process and per call, with the target's
// extension (some writers pick the format by it), in its folder so renames stay on one file
// system: ".result1.tmp1234-0.xlsx".
std::string hidden_name(const fs::path& target, const char* kind) {
    static std::atomic<unsigned> counter{0};
    fs::path dir = target.parent_path();
    if (dir.empty()) dir = ".";
    return (dir / fmt::format(".{}.{}{}-{}{}", target.stem().string(), kind, ::getpid(), counter++,
                              target.extension().string())).string();
}

}  // namespace

AtomicFile::AtomicFile(std::string target) : target_(std::move(target)) {
    if (target_.empty()) throw InputError("output path is empty: give a file name");
    const fs::path p(target_);
    if (fs::is_directory(p))
        throw InputError(fmt::format("output path '{}' is a folder: give a file name", target_));
    fs::path dir = p.parent_path();
    if (dir.empty()) dir = ".";
    std::error_code ec;
    if (!fs::is_directory(dir, ec))
        throw InputError(fmt::format("output path '{}' is not writable: folder '{}' does not exist",
                                     target_, dir.string()));
    if (::access(dir.c_str(), W_OK) != 0)
        throw InputError(fmt::format("output path '{}' is not writable: no permission to write in '{}'",
                                     target_, dir.string()));
    temp_ = hidden_name(p, "tmp");
    // Registered before the file exists, so a kill at any later moment finds it.
    live_slot_ = live_temp::add(temp_);
    // Created now: a folder that looks writable but is not (/proc, a read-only mount) fails
    // here, before any work, and not halfway through writing.
    const int fd = ::open(temp_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0) {
        const int err = errno;
        live_temp::drop(live_slot_);
        throw InputError(fmt::format("output path '{}' is not writable: no file can be made in '{}' ({})", target_,
                                     dir.string(), std::strerror(err)));
    }
    ::close(fd);
}

AtomicFile::~AtomicFile() {
    if (!committed_) {
        std::error_code ec;
        fs::remove(temp_, ec);
    }
    live_temp::drop(live_slot_);
}

void AtomicFile::commit() {
    std::error_code ec;
    fs::rename(temp_, target_, ec);
    if (ec) throw write_error(ec.message());
    committed_ = true;
    // A kill between the rename and here only unlinks a name that no longer exists.
    live_temp::drop(live_slot_);
    live_slot_ = -1;
}

FileError AtomicFile::write_error(const std::string& reason) const { return FileError(target_, "write", reason); }

void commit_together(const std::vector<AtomicFile*>& files) {
    struct Backup {
        std::string path;  // empty: there was no old file
        int slot = -1;
    };
    std::vector<Backup> backups(files.size());
    const auto drop_backups = [&backups] {
        for (Backup& b : backups) {
            if (b.path.empty()) continue;
            ::unlink(b.path.c_str());
            live_temp::drop(b.slot);
        }
    };
    // A second name for each old file, so that a rename failing halfway can put back the
    // ones already replaced.
    for (size_t i = 0; i < files.size(); ++i) {
        struct stat st {};
        if (::lstat(files[i]->target_.c_str(), &st) != 0) continue;
        Backup b{hidden_name(files[i]->target_, "old"), -1};
        b.slot = live_temp::add(b.path);
        if (::link(files[i]->target_.c_str(), b.path.c_str()) != 0) {
            const int err = errno;
            live_temp::drop(b.slot);
            drop_backups();
            throw files[i]->write_error(fmt::format("cannot keep the old file while replacing it ({}); no "
                                                    "file was changed", std::strerror(err)));
        }
        backups[i] = b;
    }
    for (size_t i = 0; i < files.size(); ++i) {
        if (::rename(files[i]->temp_.c_str(), files[i]->target_.c_str()) == 0) continue;
        const int err = errno;
        for (size_t j = 0; j < i; ++j) {
            if (backups[j].path.empty()) ::unlink(files[j]->target_.c_str());
            else ::rename(backups[j].path.c_str(), files[j]->target_.c_str());
        }
        drop_backups();
        throw files[i]->write_error(fmt::format("{}; no file was changed", std::strerror(err)));
    }
    for (AtomicFile* f : files) {
        f->committed_ = true;
        live_temp::drop(f->live_slot_);
        f->live_slot_ = -1;
    }
    drop_backups();
}

}  // namespace dragon
