#include "scene/geometry/placement.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

namespace gloss {

namespace {

constexpr double kPi = 3.14159265358979323846;

double radians(double degrees) {
  return degrees * (kPi / 180.0);
}
double degrees(double radians) {
  return radians * (180.0 / kPi);
}

// a moved by whole turns to lie within half a turn of near.
double nearest_turn(double a, double near) {
  return a + 360.0 * std::round((near - a) / 360.0);
}

glm::dvec3 nearest_turns(const glm::dvec3& a, const glm::dvec3& near) {
  return {nearest_turn(a.x, near.x), nearest_turn(a.y, near.y), nearest_turn(a.z, near.z)};
}

// The transformed copy of mesh: positions placed in double and rounded once; tangents by the
// linear part (handedness flipped where it mirrors) and normals by the inverse transpose, both
// renormalised; triangles rewound where the transform mirrors, so winding and normals keep
// agreeing (as transform_mesh does).
Mesh placed_mesh(const Mesh& mesh, const ObjectTransform& t) {
  Mesh out = mesh;
  for (glm::vec3& p : out.positions) p = glm::vec3(place_point(t, glm::dvec3(p)));
  const glm::dmat3 linear = linear_part(t);
  const double det = glm::determinant(linear);
  if (det < 0.0) {
    for (glm::uvec3& tri : out.triangles) std::swap(tri.y, tri.z);
  }
  for (glm::vec4& tangent : out.tangents) {
    const glm::dvec3 m = linear * glm::dvec3(tangent.x, tangent.y, tangent.z);
    const double len = glm::length(m);
    const glm::vec3 unit =
        len > 0.0 && std::isfinite(len) ? glm::vec3(m / len) : glm::vec3(1, 0, 0);
    tangent = glm::vec4(unit, det < 0.0 ? -tangent.w : tangent.w);
  }
  if (out.normals.empty()) return out;
  const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(linear));
  for (glm::vec3& n : out.normals) {
    const glm::dvec3 m = normal_matrix * glm::dvec3(n);
    const double len = glm::length(m);
    n = len > 0.0 && std::isfinite(len) ? glm::vec3(m / len) : glm::vec3(0.0f, 1.0f, 0.0f);
  }
  return out;
}

}  // namespace

glm::dmat3 rotation_matrix(const glm::vec3& angles) {
  const double cx = std::cos(radians(angles.x)), sx = std::sin(radians(angles.x));
  const double cy = std::cos(radians(angles.y)), sy = std::sin(radians(angles.y));
  const double cz = std::cos(radians(angles.z)), sz = std::sin(radians(angles.z));
  // glm is column-major: m[column][row].
  const glm::dmat3 rx(1, 0, 0, 0, cx, sx, 0, -sx, cx);
  const glm::dmat3 ry(cy, 0, -sy, 0, 1, 0, sy, 0, cy);
  const glm::dmat3 rz(cz, sz, 0, -sz, cz, 0, 0, 0, 1);
  return rz * ry * rx;
}

glm::dmat3 linear_part(const ObjectTransform& t) {
  const glm::dvec3 s(t.scale);
  const glm::dmat3 scale(s.x, 0, 0, 0, s.y, 0, 0, 0, s.z);
  return rotation_matrix(t.rotate) * scale;
}

glm::dvec3 place_point(const ObjectTransform& t, const glm::dvec3& p) {
  const glm::dvec3 pivot(t.pivot);
  return pivot + glm::dvec3(t.translate) + linear_part(t) * (p - pivot);
}

bool is_identity(const ObjectTransform& t) {
  return t.translate == glm::vec3(0.0f) && t.rotate == glm::vec3(0.0f) &&
         t.scale == glm::vec3(1.0f);
}

glm::vec3 euler_degrees(const glm::dmat3& r, const glm::vec3& near_angles) {
  // r = Rz(c) Ry(b) Rx(a): r[0][2] = -sin b, r[1][2] = cos b sin a, r[2][2] = cos b cos a,
  // r[0][1] = cos b sin c, r[0][0] = cos b cos c (glm's m[column][row]).
  const glm::dvec3 near(near_angles);
  const double sb = std::clamp(-r[0][2], -1.0, 1.0);
  const double b = degrees(std::asin(sb));
  if (std::sqrt(r[1][2] * r[1][2] + r[2][2] * r[2][2]) < 1e-9) {
    // Gimbal lock (b = +-90 degrees): only a - c (b = 90) or a + c (b = -90) is defined; keep
    // a where it was.
    const double a = near.x;
    const double c = sb > 0.0 ? a - degrees(std::atan2(r[1][0], r[1][1]))
                              : degrees(std::atan2(-r[1][0], r[1][1])) - a;
    return glm::vec3(nearest_turns({a, b, c}, near));
  }
  const double a = degrees(std::atan2(r[1][2], r[2][2]));
  const double c = degrees(std::atan2(r[0][1], r[0][0]));
  const glm::dvec3 first = nearest_turns({a, b, c}, near);
  const glm::dvec3 second = nearest_turns({a + 180.0, 180.0 - b, c + 180.0}, near);
  const auto distance = [&](const glm::dvec3& e) {
    const glm::dvec3 d = e - near;
    return glm::dot(d, d);
  };
  return glm::vec3(distance(first) <= distance(second) ? first : second);
}

glm::vec3 own_centre(const Object& object) {
  switch (object.type) {
    case ObjectType::sphere:
      return object.params.center;
    case ObjectType::quad: {
      const glm::dvec3 sum = glm::dvec3(object.params.quad[0]) + glm::dvec3(object.params.quad[1]) +
                             glm::dvec3(object.params.quad[2]) + glm::dvec3(object.params.quad[3]);
      return glm::vec3(sum * 0.25);
    }
    case ObjectType::box:
    case ObjectType::teapot:
    case ObjectType::mesh:
      break;
  }
  const Mesh* mesh = object.shape ? object.shape.get() : object.mesh.get();
  glm::vec3 lo, hi;
  if (mesh == nullptr || !mesh_bounds(*mesh, lo, hi)) return glm::vec3(0.0f);
  return glm::vec3(0.5 * (glm::dvec3(lo) + glm::dvec3(hi)));
}

void place_object(Object& object) {
  if (object.type != ObjectType::sphere && !object.shape) object.shape = object.mesh;
  ObjectTransform& t = object.transform;
  if (!t.pivot_set) t.pivot = own_centre(object);
  const bool identity = is_identity(t);
  if (object.type == ObjectType::sphere) {
    object.center = identity ? object.params.center
                             : glm::vec3(place_point(t, glm::dvec3(object.params.center)));
    object.radius =
        identity ? object.params.radius
                 : static_cast<float>(double(object.params.radius) * std::fabs(double(t.scale.x)));
    return;
  }
  if (identity || !object.shape) {
    object.mesh = object.shape;
    return;
  }
  object.mesh = std::make_shared<const Mesh>(placed_mesh(*object.shape, t));
}

bool object_bounds(const Object& object, glm::vec3& lo, glm::vec3& hi) {
  if (object.type == ObjectType::sphere) {
    lo = object.center - glm::vec3(object.radius);
    hi = object.center + glm::vec3(object.radius);
    return true;
  }
  return object.mesh && mesh_bounds(*object.mesh, lo, hi);
}

}  // namespace gloss
