#include "asset_dir.hpp"

#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>

namespace dragon::cli {

namespace {
std::string& found() {
    static std::string dir;
    return dir;
}
}  // namespace

void find_tool_assets(const char* argv0) {
    namespace fs = std::filesystem;
    if (const char* set = std::getenv("DRAGON_ASSETS"); set && *set) {
        found() = set;
        return;
    }
    std::error_code ec;
    // The running executable itself (argv[0] may be a bare name found on $PATH, or a symlink).
    fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (ec) exe = fs::absolute(argv0 ? argv0 : "", ec);
    const fs::path dir = exe.parent_path().parent_path() / "share" / "benchdragon";
    if (fs::is_directory(dir / "themes", ec)) found() = dir.string();
}

const std::string& asset_dir() { return found(); }

}  // namespace dragon::cli
