#pragma once
// The reference path's maps (reference/, private): what a material's maps give at a hit recomputed
// in T (shading/hit_textures.h), and the pixel inspector's record of them.
#include <cstdint>

#include "reference/pixel_inspection.h"
#include "reference/reference_hit.h"
#include "shading/hit_textures.h"
#include "shading/map_frame.h"

namespace gloss {

// What the material's maps give at a hit (shading/hit_textures.h); count: the pixel's samples,
// which share its footprint.
template <class T>
MapValues<T> hit_maps(T fov_y, int height, MapFilter filter, const Object& object,
                      std::uint32_t prim, const glm::tvec3<T>& dir, int count,
                      const ReferenceHit<T>& h, const Material& m, MapFrame<T>& frame) {
  const T spread = cone_spread<T>(fov_y, height, count);
  const T cos_theta = glm::dot(dir, h.ng);
  frame = object.type == ObjectType::sphere
              ? sphere_map_frame<T>(glm::tvec3<T>(object.center), T(object.radius), h.p, h.t,
                                    spread, cos_theta)
              : mesh_map_frame<T>(*object.mesh, prim, h.b, h.t, spread, cos_theta);
  frame.n = h.n;
  frame.v = h.v;
  frame.side = h.flipped ? T(-1) : T(1);
  return map_values(m, frame, filter);
}

// The inspector's record of the maps: (u, v), footprints, and each map's level and texel.
template <class T>
void record_maps(const Material& m, const MapFrame<T>& frame, const MapValues<T>& values,
                 PixelBreakdown& out) {
  out.textured = true;
  for (int set = 0; set < 2; ++set) {
    out.uv[set] = glm::dvec2(frame.uv[set]);
    out.footprint[set] = double(frame.footprint[set]);
  }
  for (int s = 0; s < kMapSlots; ++s) {
    MapReading& r = out.maps[s];
    r.present = m.has_map(static_cast<MapSlot>(s));
    r.level = double(values.level[s]);
    r.texel = glm::dvec4(values.texel[s]);
  }
}

}  // namespace gloss
