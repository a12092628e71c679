#pragma once
// The Utah teapot's patch file (assets/models/utah-teapot.txt, whose header names its source).
#include <string>

#include "scene/geometry/teapot.h"

namespace gloss {

// Reads a 'patches N' / 'points M' file. Throws InputError naming the file and line.
BezierPatches load_bezier_patches(const std::string& path);

// The shipped teapot patches, loaded once (thread-safe) and kept, the lid fitted to the rim.
const BezierPatches& teapot_patches();

}  // namespace gloss
