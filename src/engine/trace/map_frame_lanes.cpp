#include "engine/trace/map_frame_lanes.h"

#include <cmath>
#include <cstddef>
#include <limits>

#include "engine/simd/lane_gather.h"
#include "engine/trace/sample_packet.h"
#include "shading/map_frame.h"

namespace gloss {

namespace {

// A lane's triangle as mesh_map_frame reads it, one row of kLanes floats per field: the corners'
// positions, each set's (u, v) (set 0's twice on a mesh with one set), the corners' tangents
// where the mesh has its own, and three flags as 1 or 0.
constexpr int position_row(int corner, int axis) {
  return 3 * corner + axis;
}
constexpr int uv_row(int set, int corner, int axis) {
  return 9 + 6 * set + 2 * corner + axis;
}
constexpr int tangent_row(int corner, int axis) {
  return 21 + 3 * corner + axis;
}
constexpr int kHandednessRow = 30;   // the first corner's w
constexpr int kOwnTangentsRow = 31;  // the mesh's tangents (else dp/du's)
constexpr int kFramedRow = 32;       // a textured mesh's triangle (else the default frame)
constexpr int kCornerRows = 33;

struct CornerLanes {
  alignas(64) float row[kCornerRows][kLanes];
};

void fetch_corners(const Mesh& mesh, std::uint32_t prim, int i, CornerLanes& c) {
  const glm::uvec3 tri = mesh.triangles[prim];
  const unsigned corner[3] = {tri.x, tri.y, tri.z};
  const bool own = mesh.tangents.size() == mesh.positions.size();
  for (int k = 0; k < 3; ++k) {
    const glm::vec3& p = mesh.positions[corner[k]];
    for (int a = 0; a < 3; ++a) c.row[position_row(k, a)][i] = p[a];
    for (int set = 0; set < 2; ++set) {
      const glm::vec2& uv = mesh.uv_set(set)[corner[k]];
      c.row[uv_row(set, k, 0)][i] = uv.x;
      c.row[uv_row(set, k, 1)][i] = uv.y;
    }
    const glm::vec4 t = own ? mesh.tangents[corner[k]] : glm::vec4(0.0f);
    for (int a = 0; a < 3; ++a) c.row[tangent_row(k, a)][i] = t[a];
  }
  c.row[kHandednessRow][i] = own && mesh.tangents[tri.x].w < 0.0f ? -1.0f : 1.0f;
  c.row[kOwnTangentsRow][i] = own ? 1.0f : 0.0f;
  c.row[kFramedRow][i] = 1.0f;
}

// mesh_map_frame's default frame (no (u, v), or a primitive the mesh does not have); the side
// from the face where the triangle exists (as lane_frame's `outward`), else +1.
void default_corners(const Mesh& mesh, std::uint32_t prim, int i, CornerLanes& c) {
  for (auto& row : c.row) row[i] = 0.0f;
  if (prim >= mesh.triangles.size()) return;
  const glm::uvec3 t = mesh.triangles[prim];
  const unsigned corner[3] = {t.x, t.y, t.z};
  for (int k = 0; k < 3; ++k) {
    for (int a = 0; a < 3; ++a) c.row[position_row(k, a)][i] = mesh.positions[corner[k]][a];
  }
}

}  // namespace

void map_frame_lanes(const SamplePacket& packet, const Scene& scene, const SurfaceLanes& surfaces,
                     float spread, std::uint32_t mask, MapFrameLanes& out) {
  // The triangles of the lanes, each fetched once into a column of `distinct` (a row of 16
  // pixels meets a few: two per wall, a handful of the teapot's), then spread to the lanes by
  // one permute per field (LaneGather): fetching the corners per lane from the meshes' arrays
  // cost as much as the rest of the frame.
  CornerLanes distinct;  // columns [0, count) written below, the only ones read (no 2.1 KB memset)
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
    } else {
      default_corners(mesh, packet.prim[i], count, distinct);
    }
    ++count;
  }
  CornerLanes c;
  if (count > 0) {
    const LaneGather spread_to_lanes(slot);
    for (int row = 0; row < kCornerRows; ++row) {
      spread_to_lanes(distinct.row[row], static_cast<std::size_t>(count), c.row[row]);
    }
  } else {  // only spheres: their frames below; the loop's values are not used
    c = CornerLanes{};
  }
  const float min_cos = static_cast<float>(kMinFootprintCos);
  TangentLanes& tangents = out.tangents;
  alignas(64) float footprint[2][kLanes];
#pragma omp simd
  for (int i = 0; i < kLanes; ++i) {
    auto at = [&c, i](int row) { return c.row[row][i]; };
    const float b0 = 1.0f - packet.u[i] - packet.v[i], b1 = packet.u[i], b2 = packet.v[i];
    const float gx = surfaces.gx[i], gy = surfaces.gy[i], gz = surfaces.gz[i];
    const float cos_theta = static_cast<float>(packet.dir_x[i]) * gx +
                            static_cast<float>(packet.dir_y[i]) * gy +
                            static_cast<float>(packet.dir_z[i]) * gz;
    const float cone = std::fabs(cos_theta);
    const float width = packet.t[i] * spread / (cone > min_cos ? cone : min_cos);
    // Edges and the face's cross product (its world area twice, and the side it faces). Written
    // out per axis and set: GCC 12 does not vectorise a loop around small inner loops.
    auto edge = [&](int corner, int axis) {
      return at(position_row(corner, axis)) - at(position_row(0, axis));
    };
    const float e1x = edge(1, 0), e1y = edge(1, 1), e1z = edge(1, 2);
    const float e2x = edge(2, 0), e2y = edge(2, 1), e2z = edge(2, 2);
    const float fx = e1y * e2z - e2y * e1z, fy = e1z * e2x - e2z * e1x, fz = e1x * e2y - e2x * e1y;
    const float world = std::sqrt(fx * fx + fy * fy + fz * fz);
    const std::int32_t framed = at(kFramedRow) != 0.0f ? 1 : 0;
    // Each set's (u, v), and its footprint: the cone's width times rho = sqrt(A_uv / A_world)
    // (triangle_uv_density), the set's (u, v) area over the face's.
    auto set_lanes = [&](int set) {
      auto t = [&](int corner, int axis) { return at(uv_row(set, corner, axis)); };
      out.u[set][i] = framed != 0 ? b0 * t(0, 0) + b1 * t(1, 0) + b2 * t(2, 0) : 0.0f;
      out.v[set][i] = framed != 0 ? b0 * t(0, 1) + b1 * t(1, 1) + b2 * t(2, 1) : 0.0f;
      const float ax = t(1, 0) - t(0, 0), ay = t(1, 1) - t(0, 1);
      const float bx = t(2, 0) - t(0, 0), by = t(2, 1) - t(0, 1);
      const float uv_area = std::fabs(ax * by - ay * bx);
      const float rho =
          world > 0.0f
              ? (world <= std::numeric_limits<float>::max() ? std::sqrt(uv_area / world) : 0.0f)
              : 0.0f;
      footprint[set][i] = framed != 0 ? width * rho : 0.0f;
    };
    set_lanes(0);
    set_lanes(1);
    // The tangent: the mesh's own interpolated, else set 0's dp/du where it has a length, else
    // (1, 0, 0) (triangle_uv_derivatives and mesh_map_frame).
    const float ax = at(uv_row(0, 1, 0)) - at(uv_row(0, 0, 0));
    const float ay = at(uv_row(0, 1, 1)) - at(uv_row(0, 0, 1));
    const float bx = at(uv_row(0, 2, 0)) - at(uv_row(0, 0, 0));
    const float by = at(uv_row(0, 2, 1)) - at(uv_row(0, 0, 1));
    const float det = ax * by - ay * bx;
    const float dx = std::fabs(det) > 0.0f ? (by * e1x - ay * e2x) / det : 0.0f;
    const float dy = std::fabs(det) > 0.0f ? (by * e1y - ay * e2y) / det : 0.0f;
    const float dz = std::fabs(det) > 0.0f ? (by * e1z - ay * e2z) / det : 0.0f;
    auto tangent = [&](int axis) {
      return b0 * at(tangent_row(0, axis)) + b1 * at(tangent_row(1, axis)) +
             b2 * at(tangent_row(2, axis));
    };
    const float mx = tangent(0), my = tangent(1), mz = tangent(2);
    // 2: the mesh's own tangent, 1: dp/du (it has a length), 0: (1, 0, 0).
    const std::int32_t source =
        framed * (at(kOwnTangentsRow) != 0.0f
                      ? 2
                      : static_cast<std::int32_t>(std::sqrt(dx * dx + dy * dy + dz * dz) > 0.0f));
    tangents.tx[i] = source == 2 ? mx : (source == 1 ? dx : 1.0f);
    tangents.ty[i] = source == 2 ? my : (source == 1 ? dy : 0.0f);
    tangents.tz[i] = source == 2 ? mz : (source == 1 ? dz : 0.0f);
    tangents.handedness[i] = framed != 0 ? at(kHandednessRow) : 1.0f;
    tangents.side[i] = fx * gx + fy * gy + fz * gz < 0.0f ? -1.0f : 1.0f;
  }
  // log2 of each set's footprint as map_values takes it, with the C library's scalar log2f
  // (libmvec's vector log2f rounds differently on 3 % of inputs, and differently again on AVX2
  // and AVX-512: the images of the two would then differ).
  for (std::uint32_t rest = mask & ~spheres; rest != 0; rest &= rest - 1) {
    const int i = __builtin_ctz(rest);
    const float log0 = std::log2(footprint[0][i]);
    out.log_footprint[0][i] = log0;
    out.log_footprint[1][i] =
        footprint[1][i] == footprint[0][i] ? log0 : std::log2(footprint[1][i]);
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
