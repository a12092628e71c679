#pragma once
// Locating the shipped assets (presets table, teapot patches, scenes) at run time.
#include <string>

namespace gloss {

// The assets folder: $GLOSS_ASSETS when set, else the source tree's assets/ (compiled-in path of
// the build), else ../share/gloss/assets beside the executable.
std::string asset_dir();

// asset_dir() + "/" + relative.
std::string asset_path(const std::string& relative);

}  // namespace gloss
