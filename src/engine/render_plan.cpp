#include "engine/render_plan.h"

#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

#include "scene/geometry/mesh.h"

namespace gloss {

namespace {
bool nonzero(const glm::vec3& c) {
  return c.x != 0.0f || c.y != 0.0f || c.z != 0.0f;
}

// Whether the eye may be inside a closed convex object (bounds widened by 1e-4 of the size, so
// that rounding can only turn shadow rays on).
bool eye_may_be_inside(const Object& object, const glm::vec3& eye) {
  if (object.type == ObjectType::sphere) {
    return glm::length(glm::dvec3(eye) - glm::dvec3(object.center)) <
           double(object.radius) * (1 + 1e-4);
  }
  glm::vec3 lo, hi;
  if (object.type != ObjectType::box || !object.mesh || !mesh_bounds(*object.mesh, lo, hi)) {
    return false;  // a quad is flat: no inside
  }
  const glm::vec3 margin = (hi - lo) * 1e-4f;
  return glm::all(glm::greaterThan(eye, lo - margin)) && glm::all(glm::lessThan(eye, hi + margin));
}

// True when some object could block the segment from a lit surface point to a light: two or more
// objects, or one that is not convex, or a closed convex one seen from inside (its far wall can
// hide a light outside). Seen from outside, a convex surface never occludes itself where ndl > 0.
// Hidden objects cast no shadow: only the visible ones count.
bool can_cast_shadows(const Scene& scene) {
  const Object* only = nullptr;
  for (const Object& o : scene.objects) {
    if (o.hidden) continue;
    if (only != nullptr) return true;
    only = &o;
  }
  if (only == nullptr) return false;
  return !is_convex(only->type) || eye_may_be_inside(*only, scene.camera.eye);
}
}  // namespace

RenderPlan make_render_plan(const Scene& scene, bool full) {
  RenderPlan plan;
  bool any_ld = false, any_ls = false;
  glm::vec3 ambient_light = scene.ambient;
  for (std::size_t i = 0; i < scene.lights.size(); ++i) {
    const Light& light = scene.lights[i];
    ambient_light += light.ambient;
    if (!full && !nonzero(light.diffuse) && !nonzero(light.specular)) continue;
    plan.lights.push_back(static_cast<int>(i));
    // A directional light has no attenuation: its factors take the unit copy of the loops.
    plan.unit_attenuation.push_back(light.type == LightType::directional ||
                                    (!full && light.attenuation == glm::vec3(1.0f, 0.0f, 0.0f)));
    plan.sources.push_back(make_light_source<float>(light, scene.camera));
    plan.sources.back().unit_attenuation = plan.unit_attenuation.back();
    any_ld = any_ld || nonzero(light.diffuse);
    any_ls = any_ls || nonzero(light.specular);
  }
  bool any_ke = false, any_ka = false, any_kd = false, any_ks = false;
  for (const Material& m : scene.materials) {
    any_ke = any_ke || nonzero(m.emission);
    any_ka = any_ka || nonzero(m.ambient);
    any_kd = any_kd || nonzero(m.diffuse);
    any_ks = any_ks || nonzero(m.specular);
  }
  plan.spheres = has_object_type(scene, ObjectType::sphere);
  // Maps of the materials some object uses.
  std::vector<bool> used(scene.materials.size(), false);
  for (const Object& o : scene.objects) {
    if (o.material >= 0 && o.material < static_cast<int>(used.size())) used[o.material] = true;
  }
  TexturePlan& t = plan.textures;
  for (std::size_t m = 0; m < scene.materials.size(); ++m) {
    if (!used[m]) continue;
    const Material& mat = scene.materials[m];
    t.kd = t.kd || mat.has_map(MapSlot::diffuse);
    t.ka = t.ka || mat.has_map(MapSlot::ambient);
    t.ks = t.ks || mat.has_map(MapSlot::specular);
    t.ke = t.ke || mat.has_map(MapSlot::emission);
    t.alpha = t.alpha || mat.has_map(MapSlot::shininess);
    t.normals = t.normals || mat.has_map(MapSlot::normal) || mat.has_map(MapSlot::bump);
  }
  t.filter = scene.render.map_filter;
  const bool environment = scene.environment.present();
  plan.sky = environment;
  if (full) {
    plan.shadow_rays = scene.render.shadows;
    plan.emissive = plan.ambient = plan.diffuse = plan.specular = true;
    plan.environment = environment;
    return plan;
  }
  plan.emissive = any_ke;
  plan.ambient = any_ka && nonzero(ambient_light);
  plan.diffuse = any_kd && any_ld;
  plan.specular = any_ks && any_ls;
  // An environment at intensity 0 is still planned: its intensity is a recombination constant
  // (a `shade` edit), so turning it up again traces nothing.
  plan.environment = environment && (any_kd || any_ks);
  const bool lights_lit = plan.diffuse || plan.specular;
  plan.diffuse = plan.diffuse || (plan.environment && any_kd);
  plan.specular = plan.specular || (plan.environment && any_ks);
  if (!lights_lit) {  // lights then only feed the ambient sum
    plan.lights.clear();
    plan.unit_attenuation.clear();
    plan.sources.clear();
  }
  plan.shadow_rays = scene.render.shadows && !plan.lights.empty() && can_cast_shadows(scene);
  return plan;
}

}  // namespace gloss
