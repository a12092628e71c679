#pragma once
// Per-primitive data that shading a hit needs, flattened over the scene into arrays so the
// packet code (sample_packet.cpp) fetches a lane's with one index, not through object, mesh and
// triangle indices: for a triangle its unit face normal and, on smooth meshes, its three vertex
// normals and their tangent planes (surface.h terminator_lift); for a sphere its centre. Built with
// the Embree scene (embree_scene.h).
#include <array>
#include <cstdint>
#include <vector>

#include "scene/scene.h"

namespace gloss {

enum PrimitiveKind : std::int32_t { kFlatTriangle = 0, kSmoothTriangle = 1, kSphere = 2 };

struct SurfaceTable {
  // Record of primitive p of object k: base[k] + p stride[k]. Record 0 is a placeholder for
  // missed lanes (a sphere centred at (1, 1, 1)): any valid input, its result is discarded.
  // A flat mesh whose triangles share one face normal (a wall) has one record for them all,
  // stride 0: the lanes of a packet on it then fetch one entry, a broadcast (lane_gather.h).
  std::vector<std::uint32_t> base;
  std::vector<std::uint32_t> stride;          // 1, or 0 for a single record
  std::vector<std::int32_t> kind;             // PrimitiveKind of each object's primitives
  std::array<std::vector<float>, 3> a;        // sphere centre, or unit face normal (x, y, z)
  std::array<std::vector<float>, 9> normals;  // n0, n1, n2 of smooth triangles (x, y, z each)
  std::array<std::vector<float>, 3> planes;   // dot(P_k, n_k) of smooth triangles' corners

  std::uint32_t record(std::int32_t object, std::uint32_t prim) const {
    const std::size_t k = static_cast<std::size_t>(object);
    return object < 0 ? 0u : base[k] + prim * stride[k];
  }
};

SurfaceTable make_surface_table(const Scene& scene);

}  // namespace gloss
