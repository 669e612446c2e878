// Where the tool's assets (themes, scenario presets, storyboards' presets) are.
#pragma once

#include <string>

namespace dragon::cli {

// Finds the tool's assets once, for asset_dir(): $DRAGON_ASSETS if set, else share/benchdragon
// beside the executable's folder (<prefix>/bin/dragon -> <prefix>/share/benchdragon when
// installed; build/src/dragon -> build/share/benchdragon, where the build copies assets/) if
// that folder holds the themes, else "" (the library's own lookup). No path is built into the
// binary, and nothing is set for the library: every call that looks for an asset is given this
// folder.
void find_tool_assets(const char* argv0);
// The folder find_tool_assets found ("" before it, or when none was).
const std::string& asset_dir();

}  // namespace dragon::cli
