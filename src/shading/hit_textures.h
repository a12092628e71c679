#pragma once
// What a material's maps give at a hit (docs/spec/shading.md, "Textures"), over a scalar type:
// the multipliers of ka, kd, ks, ke and alpha, and the shading normal after its normal or bump
// map. Every lookup reads its map at the level of the hit's footprint (texture/footprint.h),
// or as a knob says (MapFilter). The reference path calls this per sample; the renderer's lanes
// make the same calls (engine/trace/texture_lanes.cpp); the GLSL path mirrors it.
#include <array>
#include <cmath>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "scene/material.h"
#include "shading/texturing.h"
#include "texture/footprint.h"
#include "texture/texture_lookup.h"

namespace gloss {

// The surface at a hit as the maps need it.
template <class T>
struct MapFrame {
  // (u, v) of each set (a shape with one set has it twice); (0, 0) on a mesh without (u, v)
  glm::vec<2, T> uv[2] = {glm::vec<2, T>(0), glm::vec<2, T>(0)};
  T footprint[2] = {T(0), T(0)};             // the sample's footprint in each set's (u, v) units
  glm::vec<3, T> n{T(0)};                    // the shading normal, on the viewer's side
  glm::vec<3, T> v{T(0)};                    // to the eye
  T side = T(1);                             // -1 where the two-sided rule turned n around
  glm::vec<3, T> tangent{T(1), T(0), T(0)};  // set 0's tangent as the mesh gives it (not turned)
  T handedness = T(1);
  glm::vec<3, T> dpdu{T(0)}, dpdv{T(0)};  // set 0's derivatives (bump maps); 0: the tangent frame's
};

// What the maps give; 1 (and n unchanged) where a material has no map.
template <class T>
struct MapValues {
  glm::vec<3, T> kd{T(1)}, ka{T(1)}, ks{T(1)}, ke{T(1)};
  T alpha = T(1);
  glm::vec<3, T> n{T(0)};
  // For the inspector: each map's level read and texel, by MapSlot.
  T level[kMapSlots] = {};
  glm::vec<4, T> texel[kMapSlots] = {};
};

// The level a map is read at for a footprint (before the pyramid clamps it), from the
// footprint or from its log2 (footprint_level's first term, shared by the maps of one set).
template <class T>
T map_level_of_log(const TextureMap& map, T log2_footprint) {
  const Texture& t = *map.texture;
  return log2_footprint + texel_density_log2(t.width(), t.height(), static_cast<T>(map.scale.x),
                                             static_cast<T>(map.scale.y));
}
template <class T>
T map_level(const TextureMap& map, T footprint) {
  return map_level_of_log(map, std::log2(footprint));
}

template <class T>
glm::vec<4, T> read_map(const TextureMap& map, MapFilter filter, const glm::vec<2, T>& uv,
                        T level) {
  const glm::vec<2, T> m = map_coordinates(map, uv);
  return sample_texture(*map.texture, filter, level, m.x, m.y, map.wrap[0], map.wrap[1]);
}

// The opacity test (a cut-out is a shape, read at level 0, not blended over the footprint): the
// map's alpha where it has one, else its first channel, at least 0.5 to be a surface.
template <class T>
bool opaque_at(const TextureMap& map, const glm::vec<2, T>& uv) {
  const glm::vec<4, T> texel = read_map(map, MapFilter::bilinear, uv, T(0));
  return (map.texture->has_alpha ? texel.w : texel.x) >= T(0.5);
}

// The normal a normal map's texel makes of n (the surface's own orientation: side * frame.n),
// in the frame's tangent frame.
template <class T>
glm::vec<3, T> normal_map_normal(const Material& material, const TextureMap& map,
                                 const MapFrame<T>& frame, const glm::vec<3, T>& n,
                                 const glm::vec<4, T>& texel) {
  glm::vec<3, T> n_t = tangent_space_normal(texel, static_cast<T>(material.normal_scale));
  // A map turned or mirrored in (u, v) turns its tangent-space x and y back.
  if (map.rotation != 0.0f || map.scale.x < 0.0f || map.scale.y < 0.0f) {
    const T angle = -static_cast<T>(map.rotation) * T(3.14159265358979323846) / T(180);
    const T c = std::cos(angle), s = std::sin(angle);
    const T x = c * n_t.x - s * n_t.y, y = s * n_t.x + c * n_t.y;
    n_t.x = map.scale.x < 0.0f ? -x : x;
    n_t.y = map.scale.y < 0.0f ? -y : y;
  }
  return normal_from_map(n, frame.tangent, frame.handedness, n_t);
}

template <class T>
MapValues<T> map_values(const Material& material, const MapFrame<T>& frame, MapFilter filter) {
  MapValues<T> out;
  out.n = frame.n;
  if (!material.map_storage) return out;
  // The maps by slot, looked up once (Material::map is out of line), and log2 of each set's
  // footprint once for every map that reads the set: a renderer makes this call per sample.
  const std::array<TextureMap, kMapSlots>& maps = *material.map_storage;
  const T log_footprint0 = std::log2(frame.footprint[0]);
  const T log_footprint[2] = {log_footprint0, frame.footprint[1] == frame.footprint[0]
                                                  ? log_footprint0
                                                  : std::log2(frame.footprint[1])};
  auto map_of = [&](MapSlot slot) -> const TextureMap& { return maps[static_cast<int>(slot)]; };
  auto set_of = [&](MapSlot slot) { return map_of(slot).uv_set == 1 ? 1 : 0; };
  auto read = [&](MapSlot slot, const glm::vec<2, T>& uv) {
    const TextureMap& map = map_of(slot);
    const T level = map_level_of_log(map, log_footprint[set_of(slot)]);
    const int s = static_cast<int>(slot);
    out.level[s] = clamp_level(*map.texture, level);
    out.texel[s] = read_map(map, filter, uv, level);
    return out.texel[s];
  };
  auto uv_of = [&](MapSlot slot) { return frame.uv[set_of(slot)]; };
  auto has = [&](MapSlot slot) { return map_of(slot).present(); };
  if (has(MapSlot::diffuse)) {
    out.kd = glm::vec<3, T>(read(MapSlot::diffuse, uv_of(MapSlot::diffuse)));
    out.ka = out.kd;
  }
  if (has(MapSlot::ambient)) {
    out.ka = glm::vec<3, T>(read(MapSlot::ambient, uv_of(MapSlot::ambient)));
  }
  if (has(MapSlot::specular)) {
    out.ks = glm::vec<3, T>(read(MapSlot::specular, uv_of(MapSlot::specular)));
  }
  if (has(MapSlot::emission)) {
    out.ke = glm::vec<3, T>(read(MapSlot::emission, uv_of(MapSlot::emission)));
  }
  if (has(MapSlot::shininess)) {
    out.alpha = read(MapSlot::shininess, uv_of(MapSlot::shininess)).x;
  }
  if (has(MapSlot::opacity)) {
    const int s = static_cast<int>(MapSlot::opacity);
    out.texel[s] =
        read_map(map_of(MapSlot::opacity), MapFilter::bilinear, uv_of(MapSlot::opacity), T(0));
  }
  // The normal maps work in the surface's own orientation (the side it was modelled with), then
  // turn with it: on the back of a two-sided surface a bump is a dent.
  const glm::vec<3, T> n0 = frame.side * frame.n;
  glm::vec<3, T> n = n0;
  if (has(MapSlot::normal)) {
    const glm::vec<4, T> texel = read(MapSlot::normal, uv_of(MapSlot::normal));
    n = normal_map_normal(material, map_of(MapSlot::normal), frame, n, texel);
  }
  if (has(MapSlot::bump)) {
    const glm::vec<2, T> uv = uv_of(MapSlot::bump);
    const int set = set_of(MapSlot::bump);
    const T du = bump_step(frame.footprint[set]);
    const T scale = static_cast<T>(material.bump_scale);
    const T h = scale * read(MapSlot::bump, uv).x;
    const TextureMap& map = map_of(MapSlot::bump);
    const T level = map_level_of_log(map, log_footprint[set]);
    const T h_u = scale * read_map(map, filter, uv + glm::vec<2, T>(du, T(0)), level).x;
    const T h_v = scale * read_map(map, filter, uv + glm::vec<2, T>(T(0), du), level).x;
    glm::vec<3, T> dpdu = frame.dpdu, dpdv = frame.dpdv;
    if (glm::length(glm::cross(dpdu, dpdv)) == T(0)) {  // no derivatives: the tangent frame's
      dpdu = orthogonal_tangent(n, frame.tangent);
      dpdv = frame.handedness * glm::cross(n, dpdu);
    }
    n = normal_from_bump(n, dpdu, dpdv, h, h_u, h_v, du, du);
  }
  if (n != n0) out.n = facing_viewer(frame.side * n, frame.v);
  return out;
}

}  // namespace gloss
