#include "scene/geometry/tangent_space.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <unordered_map>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

namespace gloss {

namespace {

// mikktspace.c's test for "not zero": anything above the smallest normal float.
bool not_zero(float x) {
  return std::fabs(x) > FLT_MIN;
}
bool not_zero(const glm::vec3& v) {
  return not_zero(v.x) || not_zero(v.y) || not_zero(v.z);
}
glm::vec3 normalized(const glm::vec3& v) {
  return v / glm::length(v);
}
// v made perpendicular to the unit n, then normalised where it is not zero.
glm::vec3 project(const glm::vec3& v, const glm::vec3& n) {
  const glm::vec3 p = v - n * glm::dot(n, v);
  return not_zero(p) ? normalized(p) : p;
}

// A corner's attributes: what welding compares, bit for bit.
struct Corner {
  glm::vec3 position, normal;
  glm::vec2 uv;
};

struct CornerKey {
  float values[8];
  bool operator==(const CornerKey& o) const {
    return std::memcmp(values, o.values, sizeof values) == 0;
  }
};
struct CornerHash {
  std::size_t operator()(const CornerKey& k) const {
    std::uint32_t bits[8];
    std::memcpy(bits, k.values, sizeof bits);
    std::size_t h = 1469598103934665603ull;
    for (std::uint32_t b : bits) h = (h ^ b) * 1099511628211ull;
    return h;
  }
};

struct TriangleInfo {
  glm::vec3 os{0.0f}, ot{0.0f};  // unit dP/du, dP/dv directions (sign-corrected), or 0
  float mag_s = 0.0f, mag_t = 0.0f;
  bool orient = false;  // orientation-preserving: positive (u, v) area
  bool any = true;      // joins any group (no usable gradient)
  bool degenerate = false;
  int neighbour[3] = {-1, -1, -1};  // across edge i (corner i to corner i + 1)
  int group[3] = {-1, -1, -1};
};

struct Group {
  int vertex = 0;  // welded vertex
  bool orient = false;
  std::vector<int> faces;
};

struct Builder {
  const std::vector<Corner>& corners;  // 3 per triangle
  std::vector<int> welded;             // per corner: the first corner with its attributes
  std::vector<TriangleInfo> tris;
  std::vector<Group> groups;

  int corner_of(int f, int vertex) const {
    for (int i = 0; i < 3; ++i) {
      if (welded[3 * f + i] == vertex) return i;
    }
    return 0;
  }

  // AssignRecur of mikktspace.c: adds f to the group around its vertex and walks on across the
  // two edges at that vertex while orientations agree.
  void assign(int f, int g) {
    TriangleInfo& t = tris[static_cast<std::size_t>(f)];
    const int i = corner_of(f, groups[g].vertex);
    if (t.group[i] == g) return;
    if (t.group[i] >= 0) return;
    if (t.any && t.group[0] < 0 && t.group[1] < 0 && t.group[2] < 0) {
      t.orient = groups[g].orient;  // the first group it joins decides its orientation
    }
    if (t.orient != groups[g].orient) return;
    groups[g].faces.push_back(f);
    t.group[i] = g;
    const int left = t.neighbour[i], right = t.neighbour[i > 0 ? i - 1 : 2];
    if (left >= 0) assign(left, g);
    if (right >= 0) assign(right, g);
  }

  // EvalTspace: the group members' directions at the vertex, weighted by their corner angles.
  glm::vec3 evaluate(const std::vector<int>& members, int vertex) const {
    glm::vec3 os(0.0f);
    for (int f : members) {
      const TriangleInfo& t = tris[static_cast<std::size_t>(f)];
      if (t.any) continue;
      const int i = corner_of(f, vertex);
      const glm::vec3 n = corners[3 * f + i].normal;
      const glm::vec3 p0 = corners[3 * f + (i > 0 ? i - 1 : 2)].position;
      const glm::vec3 p1 = corners[3 * f + i].position;
      const glm::vec3 p2 = corners[3 * f + (i < 2 ? i + 1 : 0)].position;
      const glm::vec3 v1 = project(p0 - p1, n), v2 = project(p2 - p1, n);
      const float angle = std::acos(std::clamp(glm::dot(v1, v2), -1.0f, 1.0f));
      os += angle * project(t.os, n);
    }
    return not_zero(os) ? normalized(os) : os;
  }
};

}  // namespace

void generate_tangents(Mesh& mesh) {
  if (mesh.uv[0].size() != mesh.positions.size() || mesh.triangles.empty()) return;
  const std::size_t count = mesh.triangles.size();
  std::vector<Corner> corners(3 * count);
  for (std::size_t f = 0; f < count; ++f) {
    const glm::uvec3& tri = mesh.triangles[f];
    glm::vec3 face(0.0f, 0.0f, 1.0f);
    if (!mesh.smooth()) {
      const glm::vec3 c = glm::cross(mesh.positions[tri.y] - mesh.positions[tri.x],
                                     mesh.positions[tri.z] - mesh.positions[tri.x]);
      if (not_zero(c)) face = normalized(c);
    }
    for (int i = 0; i < 3; ++i) {
      const unsigned v = tri[i];
      corners[3 * f + i] = {mesh.positions[v], mesh.smooth() ? mesh.normals[v] : face,
                            mesh.uv[0][v]};
    }
  }

  Builder b{corners, {}, std::vector<TriangleInfo>(count), {}};
  b.welded.resize(corners.size());
  std::unordered_map<CornerKey, int, CornerHash> first;
  for (std::size_t k = 0; k < corners.size(); ++k) {
    const Corner& c = corners[k];
    const CornerKey key{{c.position.x, c.position.y, c.position.z, c.normal.x, c.normal.y,
                         c.normal.z, c.uv.x, c.uv.y}};
    b.welded[k] = first.emplace(key, static_cast<int>(k)).first->second;
  }

  // Per triangle: InitTriInfo's first-order derivatives.
  for (std::size_t f = 0; f < count; ++f) {
    TriangleInfo& t = b.tris[f];
    const int* w = &b.welded[3 * f];
    t.degenerate = w[0] == w[1] || w[1] == w[2] || w[2] == w[0];
    const Corner &c1 = corners[3 * f], &c2 = corners[3 * f + 1], &c3 = corners[3 * f + 2];
    const float t21x = c2.uv.x - c1.uv.x, t21y = c2.uv.y - c1.uv.y;
    const float t31x = c3.uv.x - c1.uv.x, t31y = c3.uv.y - c1.uv.y;
    const glm::vec3 d1 = c2.position - c1.position, d2 = c3.position - c1.position;
    const float area = t21x * t31y - t21y * t31x;
    const glm::vec3 os = t31y * d1 - t21y * d2;
    const glm::vec3 ot = -t31x * d1 + t21x * d2;
    t.orient = area > 0.0f;
    if (!not_zero(area)) continue;
    const float len_os = glm::length(os), len_ot = glm::length(ot);
    const float sign = t.orient ? 1.0f : -1.0f;
    if (not_zero(len_os)) t.os = (sign / len_os) * os;
    if (not_zero(len_ot)) t.ot = (sign / len_ot) * ot;
    t.mag_s = len_os / std::fabs(area);
    t.mag_t = len_ot / std::fabs(area);
    if (not_zero(t.mag_s) && not_zero(t.mag_t)) t.any = false;
  }

  // Neighbours across shared edges (welded corners), the first unmatched one in triangle order.
  std::map<std::pair<int, int>, std::vector<std::pair<int, int>>> edges;
  for (std::size_t f = 0; f < count; ++f) {
    if (b.tris[f].degenerate) continue;
    for (int i = 0; i < 3; ++i) {
      edges[{b.welded[3 * f + i], b.welded[3 * f + (i + 1) % 3]}].push_back(
          {static_cast<int>(f), i});
    }
  }
  for (std::size_t f = 0; f < count; ++f) {
    if (b.tris[f].degenerate) continue;
    for (int i = 0; i < 3; ++i) {
      if (b.tris[f].neighbour[i] >= 0) continue;
      const auto it = edges.find({b.welded[3 * f + (i + 1) % 3], b.welded[3 * f + i]});
      if (it == edges.end()) continue;
      for (const auto& [g, j] : it->second) {
        if (b.tris[static_cast<std::size_t>(g)].neighbour[j] >= 0 || g == static_cast<int>(f)) {
          continue;
        }
        b.tris[f].neighbour[i] = g;
        b.tris[static_cast<std::size_t>(g)].neighbour[j] = static_cast<int>(f);
        break;
      }
    }
  }

  // Build4RuleGroups: a group per vertex and orientation, grown across edges.
  for (std::size_t f = 0; f < count; ++f) {
    for (int i = 0; i < 3; ++i) {
      TriangleInfo& t = b.tris[f];
      if (t.degenerate || t.group[i] >= 0) continue;
      const int g = static_cast<int>(b.groups.size());
      b.groups.push_back({b.welded[3 * f + i], t.orient, {static_cast<int>(f)}});
      t.group[i] = g;
      const int left = t.neighbour[i], right = t.neighbour[i > 0 ? i - 1 : 2];
      if (left >= 0) b.assign(left, g);
      if (right >= 0) b.assign(right, g);
    }
  }

  // Per corner: its group's tangent. mikktspace splits a group into subgroups of similar
  // directions; with its default threshold (180 degrees) that keeps every member but exact
  // opposites, which only a group-with-any triangle could bring, so members are the whole group.
  std::vector<glm::vec4> corner_tangent(corners.size(), glm::vec4(1.0f, 0.0f, 0.0f, -1.0f));
  std::vector<bool> done(corners.size(), false);
  for (const Group& g : b.groups) {
    const glm::vec3 tangent = b.evaluate(g.faces, g.vertex);
    for (int f : g.faces) {
      const int i = b.corner_of(f, g.vertex);
      corner_tangent[3 * f + i] = glm::vec4(tangent, g.orient ? 1.0f : -1.0f);
      done[3 * f + i] = true;
    }
  }
  // DegenEpilogue: a degenerate triangle's corner takes a non-degenerate corner's with the same
  // welded vertex.
  std::unordered_map<int, std::size_t> any_corner;
  for (std::size_t k = 0; k < corners.size(); ++k) {
    if (done[k]) any_corner.emplace(b.welded[k], k);
  }
  for (std::size_t k = 0; k < corners.size(); ++k) {
    if (done[k]) continue;
    const auto it = any_corner.find(b.welded[k]);
    if (it != any_corner.end()) corner_tangent[k] = corner_tangent[it->second];
  }

  // One vertex per (vertex, tangent); the first keeps its index.
  std::vector<glm::vec4> tangents(mesh.positions.size());
  std::vector<bool> set(mesh.positions.size(), false);
  std::map<std::pair<unsigned, std::vector<float>>, unsigned> split;
  for (std::size_t f = 0; f < count; ++f) {
    for (int i = 0; i < 3; ++i) {
      unsigned& v = mesh.triangles[f][i];
      const glm::vec4& tangent = corner_tangent[3 * f + i];
      if (!set[v]) {
        set[v] = true;
        tangents[v] = tangent;
        continue;
      }
      if (std::memcmp(&tangents[v], &tangent, sizeof tangent) == 0) continue;
      const std::pair<unsigned, std::vector<float>> key{
          v, {tangent.x, tangent.y, tangent.z, tangent.w}};
      const auto it = split.find(key);
      if (it != split.end()) {
        v = it->second;
        continue;
      }
      const auto copy = static_cast<unsigned>(mesh.positions.size());
      mesh.positions.push_back(mesh.positions[v]);
      if (mesh.smooth()) mesh.normals.push_back(mesh.normals[v]);
      for (auto& uv_set : mesh.uv) {
        if (!uv_set.empty()) uv_set.push_back(uv_set[v]);
      }
      tangents.push_back(tangent);
      set.push_back(true);
      split.emplace(key, copy);
      v = copy;
    }
  }
  mesh.tangents = std::move(tangents);
}

}  // namespace gloss
