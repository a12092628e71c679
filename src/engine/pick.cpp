#include "engine/pick.h"

#include <cmath>
#include <limits>

#include "engine/trace/embree_scene.h"
#include "scene/camera.h"

namespace gloss {

namespace {

// Index of the object the ray from origin along dir meets first, -1 for none; t: its distance.
int first_hit(const EmbreeScene& embree, const glm::vec3& origin, const glm::vec3& dir, float& t) {
  RTCRayHit rh{};
  rh.ray.org_x = origin.x;
  rh.ray.org_y = origin.y;
  rh.ray.org_z = origin.z;
  rh.ray.dir_x = dir.x;
  rh.ray.dir_y = dir.y;
  rh.ray.dir_z = dir.z;
  rh.ray.tnear = 0.0f;
  rh.ray.tfar = std::numeric_limits<float>::infinity();
  rh.ray.mask = 0xffffffffu;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  rtcIntersect1(embree.handle(), &context, &rh);
  t = rh.ray.tfar;
  return rh.hit.geomID == RTC_INVALID_GEOMETRY_ID ? -1 : static_cast<int>(rh.hit.geomID);
}

}  // namespace

int pick_object(const Scene& scene, int width, int height, float px, float py) {
  if (width <= 0 || height <= 0 || scene.objects.empty()) return -1;
  const EmbreeScene embree(scene);  // a click is rare; a fresh build keeps this stateless
  const CameraFrame frame = make_camera_frame(scene.camera, width, height);
  const glm::vec3 dir = primary_direction(frame, px, py, width, height);
  float t = 0.0f;
  return first_hit(embree, frame.eye, dir, t);
}

std::vector<SurfaceBelow> surfaces_below(const Scene& scene, const std::vector<glm::vec3>& points) {
  std::vector<SurfaceBelow> out(points.size());
  if (scene.objects.empty()) return out;
  const EmbreeScene embree(scene);
  for (std::size_t i = 0; i < points.size(); ++i) {
    float t = 0.0f;
    out[i].object = first_hit(embree, points[i], glm::vec3(0.0f, -1.0f, 0.0f), t);
    if (out[i].object >= 0) out[i].y = points[i].y - t;
  }
  return out;
}

std::vector<bool> seen_from_eye(const Scene& scene, const std::vector<glm::vec3>& points) {
  std::vector<bool> out(points.size(), true);
  if (scene.objects.empty()) return out;
  const EmbreeScene embree(scene);
  const glm::vec3 eye = scene.camera.eye;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const glm::vec3 d = points[i] - eye;
    const float distance = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    if (!(distance > 0.0f)) continue;
    float t = 0.0f;
    out[i] = first_hit(embree, eye, d / distance, t) < 0 || t >= 0.999f * distance;
  }
  return out;
}

}  // namespace gloss
