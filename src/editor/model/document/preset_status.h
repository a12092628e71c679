#pragma once
// Whether a material still is the preset it names: the Material panel shows "gold (modified)"
// once any constant differs from the preset table's, so a tweaked preset no longer reads as it.
#include <string>

#include "scene/material.h"

namespace gloss {

// True when material names a preset of the table and one of ka, kd, ks, ke or the exponent
// differs from it (exactly: a value typed back to the preset's reads as the preset again).
bool preset_modified(const Material& material);

// "gold", "gold (modified)", or "" for a material without a preset.
std::string preset_status(const Material& material);

}  // namespace gloss
