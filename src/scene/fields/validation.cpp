#include "scene/fields/validation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "base/field_path.h"
#include "base/memory_budget.h"
#include "base/text/number_text.h"
#include "scene/fields/fields.h"
#include "scene/limits.h"
#include "scene/memory/memory_estimate.h"

namespace gloss {

namespace {

// Every field of table within its kind and range (scene/fields/field.h), named under path.
template <class S>
void check_fields(const std::string& file, const std::string& path, const FieldTable<S>& table,
                  const S& value) {
  for (const Field<S>& f : table) {
    const FieldProblem problem = field_problem(f, f.get(value));
    if (problem.message.empty()) continue;
    const std::string field = child_path(path, f.key);
    fail_field(file, problem.component < 0 ? field : index_path(field, problem.component),
               problem.message);
  }
}

template <class T>
bool finite_vector(const glm::tvec3<T>& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// The camera's frame built in the precision T a renderer builds it in (float: the fast
// renderer; double: the reference path), by the renderers' own make_camera_basis, so what passes
// here cannot fail there. Throws naming the field.
template <class T>
void check_camera_in(const std::string& file, const Camera& camera, const char* precision) {
  const glm::dvec3 view = glm::dvec3(camera.target) - glm::dvec3(camera.eye);
  const std::string distance = number_text(glm::length(view));
  try {
    const CameraBasis<T> basis = make_camera_basis<T>(camera, 1, 1);
    if (!finite_vector(basis.forward) || !finite_vector(basis.right) || !finite_vector(basis.up)) {
      throw std::invalid_argument("up is parallel to the view direction");
    }
  } catch (const std::invalid_argument& error) {
    if (std::string(error.what()).find("coincide") != std::string::npos) {
      fail_field(file, "camera.target",
                 glm::length(view) == 0.0 ? std::string("must differ from camera.eye")
                                          : "is " + distance + " from camera.eye, too close for " +
                                                precision + " arithmetic to give a view direction");
    }
    fail_field(file, "camera.up",
               std::string("must not be parallel to the view direction (target - eye) nor too "
                           "short for ") +
                   precision + " arithmetic, got length " +
                   number_text(glm::length(glm::dvec3(camera.up))));
  }
}

// The rules that tie fields together: the view direction and the up hint. The fields' own
// ranges (|x| <= kMaxCoordinate) have been checked, so the differences are finite in float.
void check_camera(const std::string& file, const Camera& camera) {
  check_camera_in<float>(file, camera, "float");
  check_camera_in<double>(file, camera, "double");
}

// The pixel budget: each side within range is not enough.
void check_render(const std::string& file, const RenderSettings& render) {
  const long long pixels = static_cast<long long>(render.width) * render.height;
  if (pixels > kMaxImagePixels) {
    fail_field(file, "render",
               std::to_string(render.width) + "x" + std::to_string(render.height) + " is " +
                   std::to_string(pixels) + " pixels, more than the limit of " +
                   std::to_string(kMaxImagePixels));
  }
}

// Every type's fields are checked, those it ignores too: they are kept for a switch back.
void check_light(const std::string& file, const std::string& field, const Light& light) {
  if (light.attenuation == glm::vec3(0.0f)) {
    fail_field(file, field + ".attenuation",
               "coefficients [c0, c1, c2] must be >= 0 and not all 0");
  }
  // Normalised in double (shading/light_source.h): only an exact 0 has no direction.
  if (glm::dvec3(light.direction) == glm::dvec3(0.0)) {
    fail_field(file, field + ".direction", "must not be [0, 0, 0]: it gives the light's way");
  }
}

// The scale's rules, checked before the placed geometry: a sphere scaled by 0 has a placed radius
// of 0, and the user typed the scale, not the radius.
void check_scale(const std::string& file, const std::string& field, const Object& object) {
  const glm::vec3& scale = object.transform.scale;
  const std::string path = field + ".transform.scale";
  for (int axis = 0; axis < 3; ++axis) {
    if (scale[axis] == 0.0f) fail_field(file, path, "must not be 0 on any axis");
  }
  if (object.type == ObjectType::sphere && !(scale.x == scale.y && scale.y == scale.z)) {
    fail_field(file, path, "a sphere takes a uniform scale only (one number)");
  }
}

// The transform's fields and the placed geometry within the coordinate limit (the object's own
// fields were checked as they were read).
void check_transform(const std::string& file, const std::string& field, const Object& object) {
  const ObjectTransform& t = object.transform;
  const std::string path = field + ".transform";
  check_fields(file, path, transform_fields(), t);
  if (object.type == ObjectType::sphere || !object.mesh || object.mesh == object.shape) return;
  glm::vec3 lo, hi;
  if (!mesh_bounds(*object.mesh, lo, hi)) return;
  for (int axis = 0; axis < 3; ++axis) {
    const double reach = std::max(std::fabs(double(lo[axis])), std::fabs(double(hi[axis])));
    if (!(reach <= kMaxCoordinate)) {
      fail_field(file, path,
                 "placed vertices reach " + number_text(reach) + " on axis " +
                     std::to_string(axis) + ", beyond the limit " + number_text(kMaxCoordinate));
    }
  }
}

void check_object(const Scene& scene, std::size_t index) {
  const std::string& file = scene.path;
  const Object& object = scene.objects[index];
  const std::string field = index_path("objects", index);
  if (object.material < 0 || object.material >= static_cast<int>(scene.materials.size())) {
    fail_field(file, field + ".material",
               "material index " + std::to_string(object.material) + " is out of range");
  }
  check_scale(file, field, object);
  if (object.type == ObjectType::sphere) {
    for (int axis = 0; axis < 3; ++axis) {
      if (!(std::fabs(object.center[axis]) <= kMaxCoordinate)) {
        fail_field(file, index_path(field + ".center", axis),
                   "must be a finite number from " + number_text(-kMaxCoordinate) + " to " +
                       number_text(kMaxCoordinate) + ", got " + number_text(object.center[axis]));
      }
    }
    if (!(object.radius > 0.0f && object.radius <= kMaxCoordinate)) {
      fail_field(file, field + ".radius",
                 "must be a finite number > 0 and at most " + number_text(kMaxCoordinate) +
                     ", got " + number_text(object.radius));
    }
  } else if (!object.mesh) {
    fail_field(file, field, "has no geometry");
  }
  check_transform(file, field, object);
}

// The geometry and the render caches against the memory budget (base/memory_budget.h), before
// a renderer allocates: the object that passes it, else the render settings, are named.
void check_memory(const Scene& scene, SampleMemory samples) {
  const std::string& file = scene.path;
  const std::uint64_t budget = memory_budget_bytes();
  std::uint64_t total = 0;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const Object& object = scene.objects[i];
    if (!object.mesh) continue;
    total += geometry_bytes(object.mesh->triangles.size());
    if (total > budget) {
      fail_field(file, index_path("objects", i),
                 std::string(to_string(object.type)) + ", " +
                     std::to_string(object.mesh->triangles.size()) +
                     " triangles: the scene needs ~" + std::to_string(megabytes(total)) +
                     " MB with it, budget " + memory_budget_text());
    }
  }
  if (scene.environment.present()) {
    total += environment_bytes(scene.environment);
    if (total > budget) {
      const Image& map = scene.environment.map->radiance;
      fail_field(file, "environment.file",
                 std::to_string(map.width) + "x" + std::to_string(map.height) +
                     " map: the scene needs ~" + std::to_string(megabytes(total)) +
                     " MB with it, budget " + memory_budget_text());
    }
  }
  const std::uint64_t maps = texture_bytes(scene);
  if (maps > 0 && total + maps > budget) {
    fail_field(file, "materials",
               "the maps hold ~" + std::to_string(megabytes(maps)) + " MB: the scene needs ~" +
                   std::to_string(megabytes(total + maps)) + " MB with them, budget " +
                   memory_budget_text());
  }
  total += maps;
  const RenderSettings& r = scene.render;
  const std::uint64_t render = render_bytes(r, scene.lights.size(), samples);
  if (total + render > budget) {
    fail_field(file, "render",
               std::to_string(r.width) + "x" + std::to_string(r.height) + " at " +
                   std::to_string(r.spp) + " spp with " + std::to_string(scene.lights.size()) +
                   " light(s) needs ~" + std::to_string(megabytes(render)) + " MB besides ~" +
                   std::to_string(megabytes(total)) + " MB of geometry, budget " +
                   memory_budget_text());
  }
}

}  // namespace

void validate_scene(const Scene& scene, SampleMemory samples) {
  const std::string& file = scene.path;
  check_fields(file, "camera", camera_fields(), scene.camera);
  check_camera(file, scene.camera);
  check_fields(file, "render", render_fields(), scene.render);
  check_render(file, scene.render);
  check_fields(file, "", scene_fields(), scene);
  check_fields(file, "environment", environment_fields(), scene.environment);
  for (std::size_t i = 0; i < scene.lights.size(); ++i) {
    const std::string field = index_path("lights", i);
    check_fields(file, field, light_fields(), scene.lights[i]);
    check_light(file, field, scene.lights[i]);
  }
  if (scene.material_names.size() != scene.materials.size()) {
    fail_field(file, "materials", "every material needs a name");
  }
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    validate_material(file, child_path("materials", scene.material_names[i]), scene.materials[i]);
  }
  for (std::size_t i = 0; i < scene.objects.size(); ++i) check_object(scene, i);
  check_memory(scene, samples);
}

void validate_material(const std::string& file, const std::string& field,
                       const Material& material) {
  check_fields(file, field, material_fields(), material);
  if (material.reference) {
    check_fields(file, child_path(field, "reference"), reference_fields(), *material.reference);
  }
}

}  // namespace gloss
