#pragma once
// One map read at the lanes of a packet at once (docs/engine.md, "Maps in lanes"): where each lane
// reads (the map's coordinates, the level of its footprint, the four texels of each level and
// their weights) in vector loops over all lanes, then per lane the texel reads and the blend.
// The same operations in the same order as shading/hit_textures.h read_map<float> with the
// trilinear or bilinear filter (texture/texture_lookup.h), so the values are read_map's: per
// lane, the scalar path spent most of its time on the per-lookup set-up (coordinate range, floor,
// wrap branches, 64-bit indices, level clamps) that is here one vector loop for 16 lanes.
#include <cstdint>

#include "engine/simd/lanes.h"
#include "scene/texture_map.h"
#include "texture/texture_lookup.h"

namespace gloss {

// What a map gives at each lane: channel c of lane i in texel[c][i] (a one-channel map as
// (g, g, g, 1)).
struct MapTexelLanes {
  alignas(64) float texel[4][kLanes];
};

// Whether map_taps and read_taps read with this filter (the nearest-texel knob goes per lane).
inline bool lane_filter(MapFilter filter) {
  return filter != MapFilter::nearest;
}

// Where lanes read one level of a map: the level, the texel offsets (row * width + column) of
// the four texels and the weights of the right column and the bottom row. 32-bit offsets: a
// level of at most 2^31 texels (32 GB of RGBA float, far past any memory budget).
struct LevelTaps {
  alignas(64) std::int32_t level[kLanes];
  alignas(64) std::int32_t t00[kLanes], t10[kLanes], t01[kLanes], t11[kLanes];
  alignas(64) float fx[kLanes], fy[kLanes];
};

// Where lanes read a map: the levels below and above each lane's footprint level, and the share
// of the one above (0: the level below alone).
struct MapTaps {
  LevelTaps near, far;
  alignas(64) float far_share[kLanes];
};

// Whether two maps (present) are read at the same texels: same level sizes, wrap, placement and
// (u, v) set (a material's colour and normal maps often are: their taps are then made once).
bool same_taps(const TextureMap& a, const TextureMap& b);

// The taps of map (present) at the lanes whose bit is set in mask, at (u[i], v[i]) of its set,
// at the level of a footprint whose log2 is log_footprint[i] (the arrays 64-byte aligned);
// filter is trilinear or bilinear (lane_filter).
void map_taps(const TextureMap& map, MapFilter filter, const float* u, const float* v,
              const float* log_footprint, std::uint32_t mask, MapTaps& taps);

// The texture's values at the taps of the lanes in mask (lanes outside it are left as they
// were): read_map<float>(map, filter, uv, map_level_of_log(map, log_footprint)) for each, its
// first `channels` (1 to 4) channels.
void read_taps(const Texture& texture, const MapTaps& taps, std::uint32_t mask, MapTexelLanes& out,
               int channels);

}  // namespace gloss
