#include "scene/validation.h"

#include <cmath>
#include <cstdio>
#include <string>

#include <glm/geometric.hpp>

#include "base/field_path.h"
#include "scene/fields.h"

namespace gloss {

namespace {

std::string number_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

// Every field of table within its kind and range (scene/field.h), named under path.
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

// The rules that tie fields together: the view direction and the up hint.
void check_camera(const std::string& file, const Camera& camera) {
  // In double so that the test is exact for any finite float input.
  const glm::dvec3 view = glm::dvec3(camera.target) - glm::dvec3(camera.eye);
  const glm::dvec3 up(camera.up);
  if (glm::length(view) == 0.0) fail_field(file, "camera.target", "must differ from camera.eye");
  if (glm::length(up) == 0.0) fail_field(file, "camera.up", "must not be zero");
  if (glm::length(glm::cross(glm::normalize(view), glm::normalize(up))) < 1e-6) {
    fail_field(file, "camera.up", "must not be parallel to the view direction (target - eye)");
  }
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

void check_light(const std::string& file, const std::string& field, const PointLight& light) {
  if (light.attenuation == glm::vec3(0.0f)) {
    fail_field(file, field + ".attenuation",
               "coefficients [c0, c1, c2] must be >= 0 and not all 0");
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
  if (object.type == ObjectType::sphere) {
    if (!(std::isfinite(object.center.x) && std::isfinite(object.center.y) &&
          std::isfinite(object.center.z))) {
      fail_field(file, field + ".center", "every component must be a finite number");
    }
    if (!(std::isfinite(object.radius) && object.radius > 0.0f)) {
      fail_field(file, field + ".radius",
                 "must be a finite number > 0, got " + number_text(object.radius));
    }
  } else if (!object.mesh) {
    fail_field(file, field, "has no geometry");
  }
}

}  // namespace

void validate_scene(const Scene& scene) {
  const std::string& file = scene.path;
  check_fields(file, "camera", camera_fields(), scene.camera);
  check_camera(file, scene.camera);
  check_fields(file, "render", render_fields(), scene.render);
  check_render(file, scene.render);
  check_fields(file, "", scene_fields(), scene);
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
}

void validate_material(const std::string& file, const std::string& field,
                       const Material& material) {
  check_fields(file, field, material_fields(), material);
}

}  // namespace gloss
