#pragma once
// Filling one lane of Embree's 16-ray packets, shared by the renderer and its baseline.
#include <limits>

#include <embree3/rtcore.h>
#include <glm/vec3.hpp>

namespace gloss {

// A ray from org along dir over [0, tfar) (dir need not be unit: t is in units of |dir|).
template <class Ray16>
inline void set_packet_ray(Ray16& ray, int lane, const glm::vec3& org, const glm::vec3& dir,
                           float tfar = std::numeric_limits<float>::infinity()) {
  ray.org_x[lane] = org.x;
  ray.org_y[lane] = org.y;
  ray.org_z[lane] = org.z;
  ray.dir_x[lane] = dir.x;
  ray.dir_y[lane] = dir.y;
  ray.dir_z[lane] = dir.z;
  ray.tnear[lane] = 0.0f;
  ray.tfar[lane] = tfar;
  ray.time[lane] = 0.0f;
  ray.mask[lane] = 0xffffffffu;
  ray.id[lane] = RTC_INVALID_GEOMETRY_ID;  // starts on no sphere (self_shadow.h); callers set it
  ray.flags[lane] = 0;
}

// Shadow rays end just short of the light: a light resting on a surface still lights the side
// it is on. Directions run from the ray's origin to the light, so t = 1 is the light.
constexpr float kShadowRayEnd = 1.0f - 1e-5f;

inline RTCIntersectContext coherent_context() {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  return context;
}

}  // namespace gloss
