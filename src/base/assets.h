#pragma once
// Locating the shipped assets (presets table, teapot patches, scenes) and the documentation at run
// time. An installed gloss finds both relative to its own executable, so any install prefix works
// (PREFIX/bin/gloss, PREFIX/share/gloss/assets, PREFIX/share/doc/gloss).
#include <string>

namespace gloss {

// The assets folder: $GLOSS_ASSETS when set; else ../share/gloss/assets beside the executable when
// that folder exists (an installed program); else the source tree's assets/ (the compiled-in path
// of a build tree); else the installed path anyway, for the error message.
std::string asset_dir();

// asset_dir() + "/" + relative.
std::string asset_path(const std::string& relative);

// The documentation folder: ../share/doc/gloss beside the executable when it exists, else the
// source tree's docs/ when it exists, else the installed path anyway.
std::string doc_dir();

// doc_dir() + "/" + relative: where --help and the Help window point a reader.
std::string doc_path(const std::string& relative);

}  // namespace gloss
