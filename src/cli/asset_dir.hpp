// Where the tool's assets (themes, scenario presets, storyboards' presets) are.
#pragma once

#include <string>

namespace dragon::cli {

// The folder of the tool's assets: $DRAGON_ASSETS if set, else share/benchdragon
// beside the executable's folder (<prefix>/bin/dragon -> <prefix>/share/benchdragon when
// installed; build/src/dragon -> build/share/benchdragon, where the build copies assets/) if
// that folder holds the themes, else "" (the library's own lookup). No path is built into the
// binary, and nothing is set for the library: main keeps the folder in the run (ToolRun::assets)
// and every call that looks for an asset is given it.
std::string find_tool_assets(const char* argv0);

}  // namespace dragon::cli
