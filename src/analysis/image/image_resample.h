#pragma once
// Resizing a linear image: how a reduced-resolution preview is shown at full size.
#include "base/image.h"

namespace gloss {

// Bilinear interpolation between pixel centres (source pixel (i, j) sits at ((i + 0.5) W / w,
// (j + 0.5) H / h) of the target), clamped to the edge pixels outside the outermost centres.
// Any sizes >= 1; equal sizes copy.
Image resize_bilinear(const Image& source, int width, int height);

}  // namespace gloss
