#include "dragon/atomic_file.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cstdio>
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
    // Hidden, unique per process and per object, same extension (some writers pick the format
    // by it), in the target's folder so the final rename stays on one file system.
    static std::atomic<unsigned> counter{0};
    const std::string name = fmt::format(".{}.tmp{}-{}{}", p.stem().string(), ::getpid(),
                                         counter++, p.extension().string());
    temp_ = (dir / name).string();
    // Registered before any writer creates the file, so a kill at any later moment finds it.
    live_slot_ = live_temp::add(temp_);
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
    if (ec) throw std::runtime_error(fmt::format("cannot write '{}': {}", target_, ec.message()));
    committed_ = true;
    // A kill between the rename and here only unlinks a name that no longer exists.
    live_temp::drop(live_slot_);
    live_slot_ = -1;
}

}  // namespace dragon
