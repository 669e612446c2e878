// Where the tool's assets (themes, scenario presets, storyboards' presets) are.
#pragma once

namespace dragon::cli {

// Unless $DRAGON_ASSETS already says where the assets are, sets it to share/benchdragon beside
// the executable's folder (<prefix>/bin/dragon -> <prefix>/share/benchdragon when installed;
// build/src/dragon -> build/share/benchdragon, where the build copies assets/) if that folder
// holds the themes. The library reads $DRAGON_ASSETS wherever it looks for an asset, so every
// lookup, the library's own included, finds the tool's copy, wherever the tool was built or
// installed; no path is built into the binary.
void point_library_at_assets(const char* argv0);

}  // namespace dragon::cli
