#include "engine/change_class.h"

#include <algorithm>

#include "engine/render_plan.h"

namespace gloss {

namespace {
ChangeClass raise(ChangeClass a, ChangeClass b) {
  return a < b ? b : a;
}

bool same_geometry(const Object& a, const Object& b) {
  if (a.type != b.type) return false;
  if (a.type == ObjectType::sphere) return a.center == b.center && a.radius == b.radius;
  return a.mesh == b.mesh;  // meshes are shared, immutable: a new mesh means new geometry
}

bool same_light_geometry(const PointLight& a, const PointLight& b) {
  return a.position == b.position && a.attenuation == b.attenuation;
}
}  // namespace

const char* to_string(ChangeClass change) {
  switch (change) {
    case ChangeClass::none:
      return "none";
    case ChangeClass::shade:
      return "shade";
    case ChangeClass::exponent:
      return "exponent";
    case ChangeClass::light:
      return "light";
    case ChangeClass::full:
      return "full";
  }
  return "?";
}

ChangeClass classify_change(const Scene& before, const Scene& after) {
  const RenderSettings& rb = before.render;
  const RenderSettings& ra = after.render;
  // Anything that moves rays: camera, image, samples, geometry.
  if (before.camera != after.camera || rb.width != ra.width || rb.height != ra.height ||
      rb.spp != ra.spp || rb.seed != ra.seed || before.objects.size() != after.objects.size()) {
    return ChangeClass::full;
  }
  ChangeClass change = ChangeClass::none;
  for (std::size_t i = 0; i < before.objects.size(); ++i) {
    if (!same_geometry(before.objects[i], after.objects[i])) return ChangeClass::full;
    if (before.objects[i].material != after.objects[i].material) {
      change = raise(change, ChangeClass::exponent);
    }
  }
  // Lights: count, positions and attenuation need new shadow rays and factors.
  if (before.lights.size() != after.lights.size() || rb.shadows != ra.shadows) {
    change = raise(change, ChangeClass::light);
  } else {
    for (std::size_t i = 0; i < before.lights.size(); ++i) {
      if (!same_light_geometry(before.lights[i], after.lights[i])) {
        change = raise(change, ChangeClass::light);
      } else if (before.lights[i] != after.lights[i]) {
        change = raise(change, ChangeClass::shade);
      }
    }
  }
  // A different plan (a light or term switched on or off) changes what the cache holds.
  if (make_render_plan(before) != make_render_plan(after))
    change = raise(change, ChangeClass::light);
  if (rb.model != ra.model || rb.pow != ra.pow) change = raise(change, ChangeClass::exponent);
  if (before.materials.size() != after.materials.size()) {
    change = raise(change, ChangeClass::exponent);
  } else {
    for (std::size_t m = 0; m < before.materials.size(); ++m) {
      const Material& a = before.materials[m];
      const Material& b = after.materials[m];
      if (a.shininess != b.shininess) {
        change = raise(change, ChangeClass::exponent);
      } else if (a != b) {
        change = raise(change, ChangeClass::shade);
      }
    }
  }
  if (before.ambient != after.ambient || before.background != after.background ||
      rb.energy_normalize != ra.energy_normalize || rb.srgb != ra.srgb) {
    change = raise(change, ChangeClass::shade);
  }
  if (change == ChangeClass::none &&
      (before.material_names != after.material_names || before.path != after.path)) {
    change = ChangeClass::shade;  // nothing to recompute, but the document did change
  }
  return change;
}

}  // namespace gloss
