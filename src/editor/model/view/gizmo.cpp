#include "editor/model/view/gizmo.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "editor/model/view/camera_controller.h"
#include "scene/geometry/placement.h"

namespace gloss {

namespace {

constexpr double kPi = 3.14159265358979323846;

struct Ray {
  glm::dvec3 origin, direction;
};

Ray mouse_ray(const Camera& camera, int width, int height, const glm::vec2& px) {
  const CameraBasis<double> basis = make_camera_basis<double>(camera, width, height);
  return {basis.eye, camera_direction<double>(basis, px.x, px.y, width, height)};
}

// The parameter s of the point centre + axis s nearest to the ray; false when they are parallel.
bool along_axis(const Ray& ray, const glm::dvec3& centre, const glm::dvec3& axis, double& s) {
  const glm::dvec3 w0 = centre - ray.origin;
  const double b = glm::dot(axis, ray.direction);
  const double denom = 1.0 - b * b;
  if (denom < 1e-6) return false;
  s = (b * glm::dot(ray.direction, w0) - glm::dot(axis, w0)) / denom;
  return true;
}

// Where the ray meets the plane through centre with normal n; false when it runs along it.
bool on_plane(const Ray& ray, const glm::dvec3& centre, const glm::dvec3& n, glm::dvec3& hit) {
  const double dn = glm::dot(ray.direction, n);
  if (std::abs(dn) < 1e-6) return false;
  const double t = glm::dot(centre - ray.origin, n) / dn;
  if (!(t > 0.0)) return false;
  hit = ray.origin + ray.direction * t;
  return true;
}

double snap_to(double value, double step) {
  return step > 0.0 ? std::round(value / step) * step : value;
}

float segment_distance(const glm::vec2& p, const glm::vec2& a, const glm::vec2& b) {
  const glm::vec2 ab = b - a;
  const float len2 = glm::dot(ab, ab);
  const float t = len2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
  return glm::length(p - (a + ab * t));
}

bool inside_quad(const glm::vec2& p, const glm::vec2 (&q)[4]) {
  float sign = 0.0f;
  for (int i = 0; i < 4; ++i) {
    const glm::vec2 e = q[(i + 1) % 4] - q[i], v = p - q[i];
    const float c = e.x * v.y - e.y * v.x;
    if (c == 0.0f) continue;
    if (sign == 0.0f) sign = c;
    if ((c > 0.0f) != (sign > 0.0f)) return false;
  }
  return true;
}

// The plane handle between axes i and j: its corners at 0.25 and 0.45 of the axis length.
void plane_corners(const GizmoFrame& f, int i, int j, glm::vec3 (&out)[4]) {
  const float a = 0.25f * f.world_length, b = 0.45f * f.world_length;
  out[0] = f.centre + f.axes[i] * a + f.axes[j] * a;
  out[1] = f.centre + f.axes[i] * b + f.axes[j] * a;
  out[2] = f.centre + f.axes[i] * b + f.axes[j] * b;
  out[3] = f.centre + f.axes[i] * a + f.axes[j] * b;
}

int axis_of(GizmoHandle h) {
  return h == GizmoHandle::x ? 0 : h == GizmoHandle::y ? 1 : h == GizmoHandle::z ? 2 : -1;
}

}  // namespace

glm::dmat3 axis_rotation(const glm::dvec3& axis, double degrees) {
  const double a = degrees * kPi / 180.0, c = std::cos(a), s = std::sin(a), t = 1.0 - c;
  const glm::dvec3 u = glm::normalize(axis);
  // Rodrigues, column by column (glm's m[column][row]).
  return glm::dmat3(t * u.x * u.x + c, t * u.x * u.y + s * u.z, t * u.x * u.z - s * u.y,
                    t * u.x * u.y - s * u.z, t * u.y * u.y + c, t * u.y * u.z + s * u.x,
                    t * u.x * u.z + s * u.y, t * u.y * u.z - s * u.x, t * u.z * u.z + c);
}

GizmoFrame gizmo_frame(const Scene& scene, const Camera& camera, const std::vector<int>& objects,
                       GizmoMode mode, int width, int height) {
  GizmoFrame f;
  f.axes[0] = {1, 0, 0};
  f.axes[1] = {0, 1, 0};
  f.axes[2] = {0, 0, 1};
  if (objects.empty() || width <= 0 || height <= 0) return f;
  glm::dvec3 sum(0.0);
  for (int i : objects) {
    const ObjectTransform& t = scene.objects[static_cast<std::size_t>(i)].transform;
    sum += glm::dvec3(t.pivot) + glm::dvec3(t.translate);
  }
  f.centre = glm::vec3(sum / static_cast<double>(objects.size()));
  if (mode == GizmoMode::scale) {  // scaling is along the primary object's own axes
    const glm::dmat3 r =
        rotation_matrix(scene.objects[static_cast<std::size_t>(objects.front())].transform.rotate);
    for (int k = 0; k < 3; ++k) f.axes[k] = glm::vec3(r[k]);
  }
  const CameraFrame basis = make_camera_frame(camera, width, height);
  const float depth = glm::dot(f.centre - basis.eye, basis.forward);
  f.visible = depth > 1e-6f;
  f.world_length = kGizmoPixels * depth * 2.0f * basis.scale_y / static_cast<float>(height);
  return f;
}

std::vector<glm::vec3> gizmo_ring(const GizmoFrame& f, int axis, int n) {
  const glm::vec3& u = f.axes[(axis + 1) % 3];
  const glm::vec3& v = f.axes[(axis + 2) % 3];
  std::vector<glm::vec3> points;
  for (int k = 0; k < n; ++k) {
    const float a = static_cast<float>(2.0 * kPi * k / n);
    points.push_back(f.centre + f.world_length * (u * std::cos(a) + v * std::sin(a)));
  }
  return points;
}

GizmoHandle gizmo_hit(const Camera& camera, int width, int height, const GizmoFrame& f,
                      GizmoMode mode, const glm::vec2& px, float tolerance) {
  glm::vec2 c;
  if (!f.visible || !project_point(camera, width, height, f.centre, c)) return GizmoHandle::none;
  const GizmoHandle axes[3] = {GizmoHandle::x, GizmoHandle::y, GizmoHandle::z};
  if (mode == GizmoMode::rotate) {
    GizmoHandle best = GizmoHandle::none;
    float nearest = tolerance;
    for (int a = 0; a < 3; ++a) {
      const std::vector<glm::vec3> ring = gizmo_ring(f, a);
      for (std::size_t k = 0; k < ring.size(); ++k) {
        glm::vec2 p, q;
        if (!project_point(camera, width, height, ring[k], p) ||
            !project_point(camera, width, height, ring[(k + 1) % ring.size()], q)) {
          continue;
        }
        const float d = segment_distance(px, p, q);
        if (d <= nearest) {
          nearest = d;
          best = axes[a];
        }
      }
    }
    return best;
  }
  if (glm::length(px - c) <= tolerance + 2.0f) return GizmoHandle::view;
  GizmoHandle best = GizmoHandle::none;
  float nearest = tolerance;
  for (int a = 0; a < 3; ++a) {
    glm::vec2 tip;
    if (!project_point(camera, width, height, f.centre + f.axes[a] * f.world_length, tip)) continue;
    const float d = segment_distance(px, c, tip);
    if (d <= nearest) {
      nearest = d;
      best = axes[a];
    }
  }
  if (best != GizmoHandle::none || mode != GizmoMode::move) return best;
  const GizmoHandle planes[3] = {GizmoHandle::xy, GizmoHandle::yz, GizmoHandle::zx};
  for (int p = 0; p < 3; ++p) {
    glm::vec3 corners[4];
    plane_corners(f, p, (p + 1) % 3, corners);
    glm::vec2 q[4];
    bool ok = true;
    for (int k = 0; k < 4; ++k) ok = ok && project_point(camera, width, height, corners[k], q[k]);
    if (ok && inside_quad(px, q)) return planes[p];
  }
  return GizmoHandle::none;
}

float gizmo_move_snap(const GizmoFrame& frame) {
  return static_cast<float>(std::pow(10.0, std::floor(std::log10(0.25 * frame.world_length))));
}

std::vector<ObjectTransform> gizmo_transforms(const Camera& camera, int width, int height,
                                              const GizmoDrag& drag, const glm::vec2& px, bool snap,
                                              glm::vec3* amount) {
  std::vector<ObjectTransform> out = drag.starts;
  const Ray from = mouse_ray(camera, width, height, drag.press);
  const Ray to = mouse_ray(camera, width, height, px);
  const GizmoFrame& f = drag.frame;
  const glm::dvec3 c(f.centre);
  const int axis = axis_of(drag.handle);
  const CameraBasis<double> basis = make_camera_basis<double>(camera, width, height);
  glm::dvec3 result(0.0);

  if (drag.mode == GizmoMode::move) {
    glm::dvec3 delta(0.0);
    const double step = snap ? gizmo_move_snap(f) : 0.0;
    if (axis >= 0) {
      const glm::dvec3 a(f.axes[axis]);
      double s0 = 0.0, s1 = 0.0;
      if (along_axis(from, c, a, s0) && along_axis(to, c, a, s1))
        delta = a * snap_to(s1 - s0, step);
    } else {
      glm::dvec3 n = basis.forward;  // view: the plane facing the camera
      if (drag.handle == GizmoHandle::xy) n = glm::dvec3(f.axes[2]);
      if (drag.handle == GizmoHandle::yz) n = glm::dvec3(f.axes[0]);
      if (drag.handle == GizmoHandle::zx) n = glm::dvec3(f.axes[1]);
      glm::dvec3 h0, h1;
      if (on_plane(from, c, n, h0) && on_plane(to, c, n, h1)) {
        delta = h1 - h0;
        if (snap) delta = {snap_to(delta.x, step), snap_to(delta.y, step), snap_to(delta.z, step)};
      }
    }
    for (ObjectTransform& t : out) t.translate = glm::vec3(glm::dvec3(t.translate) + delta);
    result = delta;
  } else if (drag.mode == GizmoMode::rotate && axis >= 0) {
    const glm::dvec3 a(f.axes[axis]);
    double degrees = 0.0;
    glm::dvec3 h0, h1;
    if (std::abs(glm::dot(to.direction, a)) > 0.2 && on_plane(from, c, a, h0) &&
        on_plane(to, c, a, h1)) {
      const glm::dvec3 v0 = h0 - c, v1 = h1 - c;
      degrees = std::atan2(glm::dot(a, glm::cross(v0, v1)), glm::dot(v0, v1)) * 180.0 / kPi;
    } else {
      // The ring is seen edge-on: the angle the cursor turns about the centre on screen, taken
      // positive when the axis points at the viewer (counter-clockwise seen from its tip).
      glm::vec2 c2;
      if (project_point(camera, width, height, f.centre, c2)) {
        const glm::dvec2 p0(drag.press.x - c2.x, c2.y - drag.press.y);
        const glm::dvec2 p1(px.x - c2.x, c2.y - px.y);
        const double ccw = std::atan2(p0.x * p1.y - p0.y * p1.x, glm::dot(p0, p1)) * 180.0 / kPi;
        degrees = glm::dot(a, basis.eye - c) > 0.0 ? ccw : -ccw;
      }
    }
    if (snap) degrees = snap_to(degrees, kGizmoRotateSnapDeg);
    const glm::dmat3 q = axis_rotation(a, degrees);
    for (std::size_t k = 0; k < out.size(); ++k) {
      const ObjectTransform& s = drag.starts[k];
      out[k].rotate = euler_degrees(q * rotation_matrix(s.rotate), s.rotate);
      const glm::dvec3 pivot(s.pivot);
      out[k].translate =
          glm::vec3(c + q * (pivot + glm::dvec3(s.translate) - c) - pivot);  // about the centre
    }
    result.x = degrees;
  } else if (drag.mode == GizmoMode::scale) {
    double k = 1.0;
    if (axis >= 0) {
      const glm::dvec3 a(f.axes[axis]);
      double s0 = 0.0, s1 = 0.0;
      if (along_axis(from, c, a, s0) && along_axis(to, c, a, s1) && std::abs(s0) > 1e-9) {
        k = s1 / s0;
      }
    } else {
      // Uniform, from the centre disc: moving the cursor away from the centre by half the
      // gizmo's length doubles the size, towards it shrinks it (the press may be at the centre,
      // where a ratio of distances would be undefined).
      glm::vec2 c2;
      if (project_point(camera, width, height, f.centre, c2)) {
        const double half = 0.5 * kGizmoPixels;
        k = (half + glm::length(px - c2) - glm::length(drag.press - c2)) / half;
      }
    }
    if (snap) k = snap_to(k, kGizmoScaleSnap);
    k = std::max(k, 0.01);
    for (std::size_t n = 0; n < out.size(); ++n) {
      const ObjectTransform& s = drag.starts[n];
      if (axis >= 0 && !drag.spheres[n]) {  // the object's own axis, about its own pivot
        out[n].scale[axis] = static_cast<float>(s.scale[axis] * k);
        continue;
      }
      out[n].scale = glm::vec3(glm::dvec3(s.scale) * k);
      const glm::dvec3 pivot(s.pivot);
      out[n].translate = glm::vec3(c + k * (pivot + glm::dvec3(s.translate) - c) - pivot);
    }
    result.x = k;
  }
  if (amount != nullptr) *amount = glm::vec3(result);
  return out;
}

}  // namespace gloss
