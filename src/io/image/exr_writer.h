#pragma once
// Writing the linear image as OpenEXR: 32-bit float R, G, B channels, unclamped, lossless ZIP
// compression, scanlines top to bottom (EXR's own order). It holds what PFM holds (the total
// before the display transform), in the format compositors and HDR viewers read.
#include <string>

#include "base/image.h"

namespace gloss {

// Writes atomically (base/atomic_file.h): a failure leaves no file. Throws RuntimeFailure.
void write_exr(const std::string& path, const Image& image);

}  // namespace gloss
