#pragma once
// A normal map's shading normals for the lanes of a packet at once (docs/engine.md, "Maps in
// lanes"): shading/hit_textures.h normal_map_normal and the horizon rule (facing_viewer) as one
// loop of selects over the lanes, the same operations in the same order, so each lane's normal
// is map_values' up to rounding (GCC contracts multiplies and adds into FMAs differently in the
// two forms: components an ulp or a few apart, more where the tangent nearly lies along n and
// Gram-Schmidt loses digits). Per lane the scalar form's three normalisations, its branches and
// the Gram-Schmidt step cost more than the map's lookup itself.
#include <cstdint>

#include "engine/simd/lanes.h"
#include "scene/material.h"

namespace gloss {

struct SurfaceLanes;  // sample_packet.h

// The lanes' frames as normal maps need them (hit_textures.h MapFrame by component).
struct TangentLanes {
  alignas(64) float tx[kLanes], ty[kLanes], tz[kLanes];  // set 0's tangent as the mesh gives it
  alignas(64) float handedness[kLanes];                  // +1 or -1
  alignas(64) float side[kLanes];  // -1 where the two-sided rule turned n around
};

// Turns the shading normals of the lanes in mask by the normal map's texels (texel[c][i]: the
// map's channel c at lane i), with map's rotation and mirroring and the material's normal_scale.
void normal_map_lanes(const Material& material, const TextureMap& map, const TangentLanes& frames,
                      const float (&texel)[4][kLanes], std::uint32_t mask, SurfaceLanes& surfaces);

}  // namespace gloss
