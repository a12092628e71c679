#pragma once
// The pixel inspector's reading as text: what `inspect X Y` prints (docs/editor.md), one value
// per line so scripts and tests can read it:
//
//   pixel X Y WIDTHxHEIGHT
//   object NAME              (none on a miss; #INDEX when the object has no name)
//   material NAME
//   alpha VALUE              energy_factor VALUE   (each on its own line)
//   total R G B              then emissive, ambient, diffuse, specular
//   lightI.ndl VALUE         then lightI.c, .c_alpha, .attenuation, .visibility,
//   lightI.diffuse R G B     .diffuse and .specular, for each light I = 0, 1, ...
#include <string>

#include "reference/pixel_inspection.h"

namespace gloss {

std::string pixel_report(const PixelBreakdown& breakdown);

}  // namespace gloss
