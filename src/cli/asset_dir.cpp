#include "asset_dir.hpp"

#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>

namespace dragon::cli {

std::string find_tool_assets(const char* argv0) {
    namespace fs = std::filesystem;
    if (const char* set = std::getenv("DRAGON_ASSETS"); set && *set) return set;
    std::error_code ec;
    // The running executable itself (argv[0] may be a bare name found on $PATH, or a symlink).
    fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (ec) exe = fs::absolute(argv0 ? argv0 : "", ec);
    const fs::path dir = exe.parent_path().parent_path() / "share" / "benchdragon";
    return fs::is_directory(dir / "themes", ec) ? dir.string() : std::string();
}

}  // namespace dragon::cli
