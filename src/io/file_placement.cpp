#include "file_placement.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>

#include <fmt/format.h>

#include "live_temp_files.hpp"
#include "dragon/errors.hpp"
#include "dragon/input_file.hpp"

namespace dragon::placement {

namespace fs = std::filesystem;

namespace {

std::string shown(const std::string& path) { return shown_text(path, 4096); }

const char* kind_of(mode_t mode) {
    if (S_ISFIFO(mode)) return "a FIFO (a named pipe)";
    if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a regular file";
}

// Copies `from` to a new hidden file beside `place` (on its file system); returns its name.
std::string copy_beside(const std::string& from, const std::string& place, const std::string& target) {
    const std::string copy = hidden_name(place, "copy");
    std::error_code ec;
    fs::copy_file(from, copy, ec);
    if (ec) {
        fs::remove(copy, ec);
        throw FileError(target, "write", fmt::format("cannot copy it across file systems ({})", ec.message()));
    }
    return copy;
}


}  // namespace

std::string hidden_name(const std::string& path, const char* kind) {
    static std::atomic<unsigned> counter{0};
    const fs::path p(path);
    fs::path dir = p.parent_path();
    if (dir.empty()) dir = ".";
    return (dir / fmt::format(".{}.{}{}-{}{}", p.stem().string(), kind, ::getpid(), counter++, p.extension().string()))
        .string();
}

std::string resolve_target(const std::string& target) {
    struct stat st {};
    if (::lstat(target.c_str(), &st) != 0) return target;  // nothing there: a new file
    std::string place = target;
    if (S_ISLNK(st.st_mode)) {
        // Written through, as cp and a shell's > write through a link; the link stays.
        std::unique_ptr<char, decltype(&std::free)> real(::realpath(target.c_str(), nullptr), &std::free);
        if (!real) {
            const int err = errno;
            char to[PATH_MAX] = {};
            const ssize_t n = ::readlink(target.c_str(), to, sizeof to - 1);
            if (err == ENOENT)
                throw InputError(fmt::format("output path '{}' is a symbolic link to '{}', which does not exist: "
                                             "remove the link or make its file first", shown(target),
                                             shown(n > 0 ? std::string(to, static_cast<std::size_t>(n)) : "?")));
            throw InputError(fmt::format("output path '{}' is a symbolic link that cannot be followed ({})",
                                         shown(target), std::strerror(err)));
        }
        place = real.get();
        if (::stat(place.c_str(), &st) != 0) return place;
    }
    if (S_ISDIR(st.st_mode))
        throw InputError(fmt::format("output path '{}' is a folder: give a file name", shown(target)));
    if (!S_ISREG(st.st_mode))
        throw InputError(fmt::format("output path '{}' is {}: give the name of a regular file", shown(target),
                                     kind_of(st.st_mode)));
    if ((st.st_mode & 0222) != 0 && ::access(place.c_str(), W_OK) != 0 && errno == EROFS)
        throw InputError(fmt::format("output path '{}' is on a read-only file system", shown(target)));
    if ((st.st_mode & 0222) == 0 || ::access(place.c_str(), W_OK) != 0)
        throw InputError(fmt::format("output path '{}' is read-only (mode {:04o}): make it writable (chmod u+w) or "
                                     "write another file", shown(target), st.st_mode & 07777));
    return place;
}

void apply_mode(const Placement& p) {
    struct stat old {};
    mode_t mode = p.new_mode;
    if (::stat(p.place.c_str(), &old) == 0 && S_ISREG(old.st_mode)) {
        mode = old.st_mode & 0777;  // no set-id bits: cp without -p drops them too
        struct stat now {};
        if (::stat(p.source.c_str(), &now) == 0 && (now.st_uid != old.st_uid || now.st_gid != old.st_gid)) {
            // The old owner and group where the system lets us (root may; a member may keep
            // the group); else the new group gets no more than everyone else.
            if (::chown(p.source.c_str(), old.st_uid, old.st_gid) != 0 &&
                ::chown(p.source.c_str(), static_cast<uid_t>(-1), old.st_gid) != 0)
                mode = (mode & ~static_cast<mode_t>(S_IRWXG)) | ((mode & S_IRWXG) & ((mode & S_IRWXO) << 3));
        }
    }
    if (::chmod(p.source.c_str(), mode) != 0)
        throw FileError(p.target, "write", fmt::format("cannot set its mode ({})", std::strerror(errno)));
}

void place_all(const std::vector<Placement>& files) {
    struct Step {
        std::string from;    // what is renamed to the place: the source, or its copy
        std::string backup;  // a second name of the old file; empty: there was none
        int slot = -1;
        bool copied = false;
    };
    std::vector<Step> steps(files.size());
    const auto cleanup = [&steps] {
        for (Step& s : steps) {
            if (!s.backup.empty()) ::unlink(s.backup.c_str());
            if (s.copied) ::unlink(s.from.c_str());
            live_temp::drop(s.slot);
        }
    };
    for (std::size_t i = 0; i < files.size(); ++i) {
        const Placement& f = files[i];
        steps[i].from = f.source;
        try {
            apply_mode(f);
            // A rename cannot cross file systems (a sweep's rows beside a link to elsewhere).
            struct stat src {}, dir {};
            fs::path folder = fs::path(f.place).parent_path();
            if (folder.empty()) folder = ".";
            if (::stat(f.source.c_str(), &src) == 0 && ::stat(folder.c_str(), &dir) == 0 && src.st_dev != dir.st_dev) {
                steps[i].from = copy_beside(f.source, f.place, f.target);
                steps[i].copied = true;
            }
        } catch (...) {
            cleanup();
            throw;
        }
        // One file needs no second name: its rename is atomic, and nothing comes after it to
        // fail. (Nor could one always be made: a file of another owner cannot be linked by
        // someone who may not read it, with protected_hardlinks.)
        struct stat st {};
        if (files.size() == 1 || ::lstat(f.place.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) continue;
        // A second name for the old file, so that a rename failing later can put it back.
        Step& s = steps[i];
        s.backup = hidden_name(f.place, "old");
        s.slot = live_temp::add(s.backup);
        if (::link(f.place.c_str(), s.backup.c_str()) != 0) {
            const int err = errno;
            s.backup.clear();
            cleanup();
            throw FileError(f.target, "write", fmt::format("cannot keep the old file while replacing it ({}); no file "
                                                           "was changed", std::strerror(err)));
        }
    }
    for (std::size_t i = 0; i < files.size(); ++i) {
        if (::rename(steps[i].from.c_str(), files[i].place.c_str()) == 0) continue;
        const int err = errno;
        for (std::size_t j = 0; j < i; ++j) {
            // Back where each came from, and the old file back in place.
            ::rename(files[j].place.c_str(), steps[j].from.c_str());
            if (!steps[j].backup.empty()) ::rename(steps[j].backup.c_str(), files[j].place.c_str());
        }
        cleanup();
        throw FileError(files[i].target, "write", fmt::format("{}{}", std::strerror(err),
                                                               files.size() > 1 ? "; no file was changed" : ""));
    }
    for (std::size_t i = 0; i < files.size(); ++i) {
        if (steps[i].copied) ::unlink(files[i].source.c_str());  // moved across: the original goes
        // A sweep's rows are kept durable to the end: the folder's new entry too.
        if (files[i].keep_source) sync_folder_of(files[i].place);
    }
    for (Step& s : steps) s.copied = false;
    cleanup();
}

void sync_folder_of(const std::string& path) {
    fs::path dir = fs::path(path).parent_path();
    if (dir.empty()) dir = ".";
    const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return;  // a folder that cannot be opened for reading: the rename still stands
    ::fsync(fd);
    ::close(fd);
}

}  // namespace dragon::placement
