#include "engine/pick.h"

#include <limits>

#include "engine/trace/embree_scene.h"
#include "scene/camera.h"

namespace gloss {

int pick_object(const Scene& scene, int width, int height, float px, float py) {
  if (width <= 0 || height <= 0 || scene.objects.empty()) return -1;
  const EmbreeScene embree(scene);  // a click is rare; a fresh build keeps this stateless
  const CameraFrame frame = make_camera_frame(scene.camera, width, height);
  const glm::vec3 dir = primary_direction(frame, px, py, width, height);
  RTCRayHit rh{};
  rh.ray.org_x = frame.eye.x;
  rh.ray.org_y = frame.eye.y;
  rh.ray.org_z = frame.eye.z;
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
  return rh.hit.geomID == RTC_INVALID_GEOMETRY_ID ? -1 : static_cast<int>(rh.hit.geomID);
}

}  // namespace gloss
