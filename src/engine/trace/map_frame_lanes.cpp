#include "engine/trace/map_frame_lanes.h"

#include <cmath>
#include <limits>

#include "engine/simd/lane_gather.h"
#include "engine/trace/sample_packet.h"
#include "shading/map_frame.h"

// glibc's libmvec has vector log2f (_ZGV{b,c,d,e}N*v_log2f, glibc >= 2.35); <math.h> declares
// it only under -ffast-math (see power_lanes.cpp for powf), so the loop below declares it.
extern "C" __attribute__((__simd__("notinbranch"))) float log2f(float) noexcept;

namespace gloss {

namespace {

// A lane's triangle as mesh_map_frame reads it: corners' positions, each set's (u, v) (set 0's
// twice on a mesh with one set), and the corners' tangents where the mesh has its own.
struct CornerLanes {
  alignas(64) float p[3][3][kLanes];      // corner, axis, lane
  alignas(64) float uv[2][3][2][kLanes];  // set, corner, axis, lane
  alignas(64) float tangent[3][3][kLanes];
  alignas(64) float handedness[kLanes];
  // Flags as floats, so that every row is an array of floats (corner_row): 1 or 0.
  alignas(64) float own_tangents[kLanes];  // the mesh's tangents (else dp/du's)
  alignas(64) float framed[kLanes];        // a textured mesh's triangle
};

void fetch_corners(const Mesh& mesh, std::uint32_t prim, int i, CornerLanes& c) {
  const glm::uvec3 tri = mesh.triangles[prim];
  const unsigned corner[3] = {tri.x, tri.y, tri.z};
  const bool own = mesh.tangents.size() == mesh.positions.size();
  for (int k = 0; k < 3; ++k) {
    const glm::vec3& p = mesh.positions[corner[k]];
    for (int a = 0; a < 3; ++a) c.p[k][a][i] = p[a];
    for (int set = 0; set < 2; ++set) {
      const glm::vec2& uv = mesh.uv_set(set)[corner[k]];
      c.uv[set][k][0][i] = uv.x;
      c.uv[set][k][1][i] = uv.y;
    }
    const glm::vec4 t = own ? mesh.tangents[corner[k]] : glm::vec4(0.0f);
    for (int a = 0; a < 3; ++a) c.tangent[k][a][i] = t[a];
  }
  c.handedness[i] = own && mesh.tangents[tri.x].w < 0.0f ? -1.0f : 1.0f;
  c.own_tangents[i] = own ? 1.0f : 0.0f;
  c.framed[i] = 1.0f;
}

// Every field of a CornerLanes as one array of kLanes floats (its layout: whole 64-byte rows).
constexpr int kCornerRows = static_cast<int>(sizeof(CornerLanes) / (sizeof(float) * kLanes));
static_assert(sizeof(CornerLanes) == kCornerRows * sizeof(float) * kLanes, "whole rows");
float* corner_row(CornerLanes& c, int row) {
  return reinterpret_cast<float*>(&c) + row * kLanes;
}

}  // namespace

void map_frame_lanes(const SamplePacket& packet, const Scene& scene, const SurfaceLanes& surfaces,
                     float spread, std::uint32_t mask, MapFrameLanes& out) {
  // The triangles of the lanes, each fetched once into a column of `distinct` (a row of 16
  // pixels meets a few: two per wall, a handful of the teapot's), then spread to the lanes by
  // one permute per field (LaneGather): fetching the corners per lane from the meshes' arrays
  // cost as much as the rest of the frame.
  CornerLanes distinct;  // columns [0, count) written below, the only ones read (no 2.3 KB memset)
  alignas(64) std::int32_t slot[kLanes] = {};
  int count = 0;
  std::int32_t last_object = -1;
  std::uint32_t last_prim = 0, spheres = 0;
  for (std::uint32_t rest = mask; rest != 0; rest &= rest - 1) {
    const int i = __builtin_ctz(rest);
    const Object& object = scene.objects[static_cast<std::size_t>(packet.object[i])];
    if (object.type == ObjectType::sphere) {
      spheres |= 1u << i;
      continue;
    }
    if (count > 0 && packet.object[i] == last_object && packet.prim[i] == last_prim) {
      slot[i] = count - 1;
      continue;
    }
    last_object = packet.object[i];
    last_prim = packet.prim[i];
    slot[i] = count;
    const Mesh& mesh = *object.mesh;
    if (mesh.textured() && packet.prim[i] < mesh.triangles.size()) {
      fetch_corners(mesh, packet.prim[i], count, distinct);
    } else {  // mesh_map_frame's default frame; the side from the face as lane_frame finds it
      for (int row = 0; row < kCornerRows; ++row) corner_row(distinct, row)[count] = 0.0f;
      const glm::uvec3 t = mesh.triangles[packet.prim[i]];
      const unsigned corner[3] = {t.x, t.y, t.z};
      for (int k = 0; k < 3; ++k) {
        for (int a = 0; a < 3; ++a) distinct.p[k][a][count] = mesh.positions[corner[k]][a];
      }
    }
    ++count;
  }
  CornerLanes c;
  if (count > 0) {
    const LaneGather spread_to_lanes(slot);
    for (int row = 0; row < kCornerRows; ++row) {
      spread_to_lanes(corner_row(distinct, row), static_cast<std::size_t>(count),
                      corner_row(c, row));
    }
  } else {  // only spheres: their frames below; the loop's values are not used
    c = CornerLanes{};
  }
  const float min_cos = static_cast<float>(kMinFootprintCos);
  TangentLanes& tangents = out.tangents;
#pragma omp simd
  for (int i = 0; i < kLanes; ++i) {
    const float b0 = 1.0f - packet.u[i] - packet.v[i], b1 = packet.u[i], b2 = packet.v[i];
    const float gx = surfaces.gx[i], gy = surfaces.gy[i], gz = surfaces.gz[i];
    const float cos_theta = static_cast<float>(packet.dir_x[i]) * gx +
                            static_cast<float>(packet.dir_y[i]) * gy +
                            static_cast<float>(packet.dir_z[i]) * gz;
    const float cone = std::fabs(cos_theta);
    const float width = packet.t[i] * spread / (cone > min_cos ? cone : min_cos);
    // Edges and the face's cross product (its world area twice, and the side it faces).
    const float e1x = c.p[1][0][i] - c.p[0][0][i], e1y = c.p[1][1][i] - c.p[0][1][i],
                e1z = c.p[1][2][i] - c.p[0][2][i];
    const float e2x = c.p[2][0][i] - c.p[0][0][i], e2y = c.p[2][1][i] - c.p[0][1][i],
                e2z = c.p[2][2][i] - c.p[0][2][i];
    const float fx = e1y * e2z - e2y * e1z, fy = e1z * e2x - e2z * e1x, fz = e1x * e2y - e2x * e1y;
    const float world = std::sqrt(fx * fx + fy * fy + fz * fz);
    const std::int32_t framed = c.framed[i] != 0.0f ? 1 : 0;
    // Each set's (u, v), and its footprint: the cone's width times rho = sqrt(A_uv / A_world)
    // (triangle_uv_density), the set's (u, v) area over the face's.
    auto set_lanes = [&](int set) {
      const float(&t)[3][2][kLanes] = c.uv[set];
      out.u[set][i] = framed != 0 ? b0 * t[0][0][i] + b1 * t[1][0][i] + b2 * t[2][0][i] : 0.0f;
      out.v[set][i] = framed != 0 ? b0 * t[0][1][i] + b1 * t[1][1][i] + b2 * t[2][1][i] : 0.0f;
      const float ax = t[1][0][i] - t[0][0][i], ay = t[1][1][i] - t[0][1][i];
      const float bx = t[2][0][i] - t[0][0][i], by = t[2][1][i] - t[0][1][i];
      const float uv_area = std::fabs(ax * by - ay * bx);
      const float rho =
          world > 0.0f
              ? (world <= std::numeric_limits<float>::max() ? std::sqrt(uv_area / world) : 0.0f)
              : 0.0f;
      return framed != 0 ? width * rho : 0.0f;
    };
    const float footprint[2] = {set_lanes(0), set_lanes(1)};
    const float log0 = log2f(footprint[0]), log1 = log2f(footprint[1]);
    out.log_footprint[0][i] = log0;
    out.log_footprint[1][i] = footprint[1] == footprint[0] ? log0 : log1;
    // The tangent: the mesh's own interpolated, else set 0's dp/du where it has a length, else
    // (1, 0, 0) (triangle_uv_derivatives and mesh_map_frame).
    const float ax = c.uv[0][1][0][i] - c.uv[0][0][0][i], ay = c.uv[0][1][1][i] - c.uv[0][0][1][i];
    const float bx = c.uv[0][2][0][i] - c.uv[0][0][0][i], by = c.uv[0][2][1][i] - c.uv[0][0][1][i];
    const float det = ax * by - ay * bx;
    const float dx = std::fabs(det) > 0.0f ? (by * e1x - ay * e2x) / det : 0.0f;
    const float dy = std::fabs(det) > 0.0f ? (by * e1y - ay * e2y) / det : 0.0f;
    const float dz = std::fabs(det) > 0.0f ? (by * e1z - ay * e2z) / det : 0.0f;
    const float(&m)[3][3][kLanes] = c.tangent;
    const float mx = b0 * m[0][0][i] + b1 * m[1][0][i] + b2 * m[2][0][i];
    const float my = b0 * m[0][1][i] + b1 * m[1][1][i] + b2 * m[2][1][i];
    const float mz = b0 * m[0][2][i] + b1 * m[1][2][i] + b2 * m[2][2][i];
    // 2: the mesh's own tangent, 1: dp/du (it has a length), 0: (1, 0, 0).
    const std::int32_t source =
        framed * (c.own_tangents[i] != 0.0f
                      ? 2
                      : static_cast<std::int32_t>(std::sqrt(dx * dx + dy * dy + dz * dz) > 0.0f));
    tangents.tx[i] = source == 2 ? mx : (source == 1 ? dx : 1.0f);
    tangents.ty[i] = source == 2 ? my : (source == 1 ? dy : 0.0f);
    tangents.tz[i] = source == 2 ? mz : (source == 1 ? dz : 0.0f);
    tangents.handedness[i] = framed != 0 ? c.handedness[i] : 1.0f;
    tangents.side[i] = fx * gx + fy * gy + fz * gz < 0.0f ? -1.0f : 1.0f;
  }
  for (std::uint32_t rest = spheres; rest != 0; rest &= rest - 1) {
    const int i = __builtin_ctz(rest);
    const Object& object = scene.objects[static_cast<std::size_t>(packet.object[i])];
    const Surface s = surfaces.get(i);
    const glm::vec3 dir(static_cast<float>(packet.dir_x[i]), static_cast<float>(packet.dir_y[i]),
                        static_cast<float>(packet.dir_z[i]));
    const MapFrame<float> f = sphere_map_frame(object.center, object.radius, s.p, packet.t[i],
                                               spread, glm::dot(dir, s.ng));
    const float log0 = std::log2(f.footprint[0]);
    for (int set = 0; set < 2; ++set) {
      out.u[set][i] = f.uv[set].x;
      out.v[set][i] = f.uv[set].y;
      out.log_footprint[set][i] = log0;
    }
    tangents.tx[i] = f.tangent.x;
    tangents.ty[i] = f.tangent.y;
    tangents.tz[i] = f.tangent.z;
    tangents.handedness[i] = f.handedness;
    tangents.side[i] = glm::dot(s.p - object.center, s.ng) < 0.0f ? -1.0f : 1.0f;
  }
}

}  // namespace gloss
