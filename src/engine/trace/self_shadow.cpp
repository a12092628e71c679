#include "engine/trace/self_shadow.h"

#include <glm/geometric.hpp>

namespace gloss {

// id = 2 * object + inside; object indices stay far below 2^31, so no id equals kNoOriginSphere.
unsigned shadow_ray_id(const Scene& scene, int object, const Surface& s) {
  if (object < 0) return kNoOriginSphere;
  const Object& o = scene.objects[static_cast<std::size_t>(object)];
  if (o.type != ObjectType::sphere) return kNoOriginSphere;
  // s.ng faces the viewer: against the outward direction p - c means the viewer is inside.
  const bool inside = glm::dot(s.ng, s.p - o.center) < 0.0f;
  return 2u * static_cast<unsigned>(object) + (inside ? 1u : 0u);
}

void drop_origin_sphere_hits(const RTCFilterFunctionNArguments* args) {
  const unsigned n = args->N;
  for (unsigned i = 0; i < n; ++i) {
    if (args->valid[i] != -1) continue;
    const unsigned id = RTCRayN_id(args->ray, n, i);
    if (id == kNoOriginSphere || id / 2u != RTCHitN_geomID(args->hit, n, i)) continue;
    const bool inside = (id & 1u) != 0;
    // Embree's sphere Ng is p - c (outward) for both roots: a ray entering has dir . Ng < 0.
    const float entering = RTCRayN_dir_x(args->ray, n, i) * RTCHitN_Ng_x(args->hit, n, i) +
                           RTCRayN_dir_y(args->ray, n, i) * RTCHitN_Ng_y(args->hit, n, i) +
                           RTCRayN_dir_z(args->ray, n, i) * RTCHitN_Ng_z(args->hit, n, i);
    if (!inside || entering < 0.0f) args->valid[i] = 0;
  }
}

}  // namespace gloss
