#include "scene/geometry/teapot.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

namespace gloss {

namespace {

// Cubic Bezier by de Casteljau. lerp is exact at t = 0 and t = 1 and when a == b, so collapsed
// control rows evaluate to exactly one point (their triangles then have exactly zero area) and
// patches sharing an edge share its corner positions exactly.
glm::dvec3 lerp(const glm::dvec3& a, const glm::dvec3& b, double t) {
  return t < 0.5 ? a + t * (b - a) : b - (1.0 - t) * (b - a);
}

struct CurvePoint {
  glm::dvec3 position;
  glm::dvec3 tangent;  // derivative with respect to the curve parameter
};

CurvePoint eval_cubic(const glm::dvec3 c[4], double t) {
  const glm::dvec3 a = lerp(c[0], c[1], t), b = lerp(c[1], c[2], t), e = lerp(c[2], c[3], t);
  const glm::dvec3 d = lerp(a, b, t), f = lerp(b, e, t);
  return {lerp(d, f, t), 3.0 * (f - d)};
}

struct SurfacePoint {
  glm::dvec3 position;
  glm::dvec3 d_s;  // dP/ds; s selects the control row (0 = first row, 1 = last)
  glm::dvec3 d_t;  // dP/dt; t runs along a control row (0 = first column, 1 = last)
};

SurfacePoint eval_patch(const glm::dvec3 control[16], double s, double t) {
  glm::dvec3 rows[4], row_tangents[4];
  for (int i = 0; i < 4; ++i) {
    const CurvePoint r = eval_cubic(control + 4 * i, t);
    rows[i] = r.position;
    row_tangents[i] = r.tangent;
  }
  const CurvePoint across = eval_cubic(rows, s);
  return {across.position, across.tangent, eval_cubic(row_tangents, s).position};
}

// The data's winding, checked once on the body: in the file's z-up frame a control row runs
// clockwise seen from above and successive rows go down, so cross(dP/dt, dP/ds) points out of the
// teapot; the other patches follow the same convention (the tests check lid, bottom and body).
bool outward_normal(const SurfacePoint& sp, glm::dvec3& n) {
  const glm::dvec3 c = glm::cross(sp.d_t, sp.d_s);
  const double scale = std::max(glm::length(sp.d_t), glm::length(sp.d_s));
  const double len = glm::length(c);
  if (!(len > 1e-10 * scale * scale) || !std::isfinite(len)) return false;
  n = c / len;
  return true;
}

// Where the derivatives' cross product vanishes (a control row or column collapsed to a pole)
// the normal is taken a little way into the patch; the lid's and bottom's poles are flat, so the
// nudge changes the direction by far less than the tessellation does.
glm::vec3 patch_normal(const glm::dvec3 control[16], double s, double t) {
  glm::dvec3 n;
  if (outward_normal(eval_patch(control, s, t), n)) return glm::vec3(n);
  for (double nudge : {1e-3, 1e-2, 1e-1}) {
    const double s2 = s < 0.5 ? s + nudge : s - nudge;
    const double t2 = t < 0.5 ? t + nudge : t - nudge;
    if (outward_normal(eval_patch(control, s2, t2), n)) return glm::vec3(n);
  }
  if (outward_normal(eval_patch(control, 0.5, 0.5), n)) return glm::vec3(n);
  return glm::vec3(0.0f, 1.0f, 0.0f);  // the whole patch is degenerate; its triangles are dropped
}

// The tangent frame of the patch's texture coordinates (u, v) = (1 - t, 1 - s) at (s, t): T is
// dP/du = -dP/dt made perpendicular to the normal n, w the sign that makes w cross(n, T) point
// along dP/dv = -dP/ds. Where dP/dt vanishes (a row collapsed to a pole: the lid's knob, the
// bottom's centre) the frame is taken a little way into the patch, as the normal is, so each of
// the pole's vertices (one per t) gets the frame of the direction it leaves the pole in.
glm::vec4 patch_tangent(const glm::dvec3 control[16], double s, double t, const glm::vec3& n) {
  const glm::dvec3 normal(n);
  auto frame = [&](const SurfacePoint& sp, glm::vec4& out) {
    const glm::dvec3 du = -sp.d_t, dv = -sp.d_s;
    const glm::dvec3 tangent = du - normal * glm::dot(normal, du);
    const double len = glm::length(tangent);
    const double scale = std::max(glm::length(sp.d_t), glm::length(sp.d_s));
    if (!(len > 1e-8 * scale) || !std::isfinite(len)) return false;
    const double w = glm::dot(glm::cross(normal, tangent), dv) < 0.0 ? -1.0 : 1.0;
    out = glm::vec4(glm::vec3(tangent / len), static_cast<float>(w));
    return true;
  };
  glm::vec4 out;
  if (frame(eval_patch(control, s, t), out)) return out;
  for (double nudge : {1e-3, 1e-2, 1e-1}) {
    const double s2 = s < 0.5 ? s + nudge : s - nudge;
    if (frame(eval_patch(control, s2, t), out)) return out;
  }
  // No direction along u anywhere near: any tangent perpendicular to n.
  const glm::dvec3 axis = std::fabs(normal.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  return glm::vec4(glm::vec3(glm::normalize(glm::cross(axis, normal))), 1.0f);
}

}  // namespace

// Vertex (i, j) of a patch sits at s = i / level (row direction), t = j / level (column
// direction). Triangles (a, b, c) and (a, c, d) of each grid cell wind like cross(dP/dt, dP/ds),
// the outward normal; a collapsed row or column makes one of the two zero-area, and those are
// dropped. Its texture coordinates are the patch's own parameters, (u, v) = (1 - t, 1 - s):
// each patch carries the whole image once, u to the right and v up seen from outside.
Mesh tessellate_patches(const BezierPatches& patches, int level, bool smooth) {
  if (level < 1 || level > 64) {
    throw std::invalid_argument("tessellate_patches: level " + std::to_string(level) +
                                " outside 1..64");
  }
  const unsigned n = static_cast<unsigned>(level) + 1;  // vertices per patch side
  Mesh mesh;
  mesh.positions.reserve(patches.patches.size() * n * n);
  if (smooth) mesh.normals.reserve(patches.patches.size() * n * n);
  mesh.triangles.reserve(patches.patches.size() * 2 * level * level);

  for (const std::array<int, 16>& patch : patches.patches) {
    glm::dvec3 control[16];
    for (int k = 0; k < 16; ++k) {
      if (patch[k] < 0 || static_cast<std::size_t>(patch[k]) >= patches.points.size()) {
        throw std::invalid_argument("tessellate_patches: control-point index out of range");
      }
      control[k] = glm::dvec3(patches.points[patch[k]]);
    }
    const auto base = static_cast<unsigned>(mesh.positions.size());
    for (unsigned i = 0; i < n; ++i) {
      const double s = static_cast<double>(i) / level;
      for (unsigned j = 0; j < n; ++j) {
        const double t = static_cast<double>(j) / level;
        mesh.positions.emplace_back(eval_patch(control, s, t).position);
        const glm::vec3 normal = patch_normal(control, s, t);
        if (smooth) mesh.normals.push_back(normal);
        mesh.uv[0].emplace_back(static_cast<float>(1.0 - t), static_cast<float>(1.0 - s));
        mesh.tangents.push_back(patch_tangent(control, s, t, normal));
      }
    }
    for (unsigned i = 0; i + 1 < n; ++i) {
      for (unsigned j = 0; j + 1 < n; ++j) {
        const unsigned a = base + i * n + j, b = a + 1, c = b + n, d = a + n;
        mesh.triangles.emplace_back(a, b, c);
        mesh.triangles.emplace_back(a, c, d);
      }
    }
  }
  drop_degenerate_triangles(mesh);
  return mesh;
}

}  // namespace gloss
