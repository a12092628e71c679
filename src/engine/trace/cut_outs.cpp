#include "engine/trace/cut_outs.h"

#include "engine/trace/self_shadow.h"
#include "shading/hit_textures.h"
#include "texture/sphere_mapping.h"

namespace gloss {

std::unique_ptr<CutOut> make_cut_out(const Scene& scene, const Object& object) {
  if (object.material < 0 || object.material >= static_cast<int>(scene.materials.size())) {
    return nullptr;
  }
  const Material& material = scene.materials[static_cast<std::size_t>(object.material)];
  if (!material.has_map(MapSlot::opacity)) return nullptr;
  auto cut = std::make_unique<CutOut>();
  cut->mesh = object.mesh;
  cut->centre = object.center;
  cut->radius = object.radius;
  cut->map = material.map(MapSlot::opacity);
  return cut;
}

void cut_out_triangles(const RTCFilterFunctionNArguments* args) {
  const auto& cut = *static_cast<const CutOut*>(args->geometryUserPtr);
  const Mesh& mesh = *cut.mesh;
  const int set = cut.map.uv_set == 1 ? 1 : 0;
  if (!mesh.textured()) return;  // no (u, v): the map's (0, 0) everywhere, tested at build
  const std::vector<glm::vec2>& uv = mesh.uv_set(set);
  const unsigned n = args->N;
  for (unsigned i = 0; i < n; ++i) {
    if (args->valid[i] != -1) continue;
    const unsigned prim = RTCHitN_primID(args->hit, n, i);
    if (prim >= mesh.triangles.size()) continue;
    const glm::uvec3 tri = mesh.triangles[prim];
    const float b1 = RTCHitN_u(args->hit, n, i), b2 = RTCHitN_v(args->hit, n, i);
    const glm::vec2 at = (1.0f - b1 - b2) * uv[tri.x] + b1 * uv[tri.y] + b2 * uv[tri.z];
    if (!opaque_at(cut.map, at)) args->valid[i] = 0;
  }
}

void cut_out_sphere(const RTCFilterFunctionNArguments* args) {
  const auto& cut = *static_cast<const CutOut*>(args->geometryUserPtr);
  const unsigned n = args->N;
  for (unsigned i = 0; i < n; ++i) {
    if (args->valid[i] != -1) continue;
    const float t = RTCRayN_tfar(args->ray, n, i);
    const glm::vec3 p(RTCRayN_org_x(args->ray, n, i) + t * RTCRayN_dir_x(args->ray, n, i),
                      RTCRayN_org_y(args->ray, n, i) + t * RTCRayN_dir_y(args->ray, n, i),
                      RTCRayN_org_z(args->ray, n, i) + t * RTCRayN_dir_z(args->ray, n, i));
    const glm::vec3 d = p - cut.centre;
    const float len = glm::length(d);
    const glm::vec2 at = sphere_uv(len > 0.0f ? d / len : glm::vec3(0.0f, 0.0f, 1.0f));
    if (!opaque_at(cut.map, at)) args->valid[i] = 0;
  }
}

void cut_out_sphere_occluded(const RTCFilterFunctionNArguments* args) {
  cut_out_sphere(args);
  drop_origin_sphere_hits(args);
}

}  // namespace gloss
