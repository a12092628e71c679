#include "scene/validation.h"

#include <cmath>
#include <cstdio>
#include <string>

#include <glm/geometric.hpp>

#include "base/field_path.h"

namespace gloss {

namespace {

bool finite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

std::string number_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

void check_finite(const std::string& file, const std::string& field, const glm::vec3& v) {
  if (!finite(v)) fail_field(file, field, "every component must be a finite number");
}

// Colours are linear RGB >= 0 (material.h, light.h); unclamped above.
void check_colour(const std::string& file, const std::string& field, const glm::vec3& c) {
  check_finite(file, field, c);
  if (c.x < 0.0f || c.y < 0.0f || c.z < 0.0f) {
    fail_field(file, field, "a colour must not be negative");
  }
}

void check_range(const std::string& file, const std::string& field, long long value, long long lo,
                 long long hi) {
  if (value < lo || value > hi) {
    fail_field(file, field,
               "must be a whole number from " + std::to_string(lo) + " to " + std::to_string(hi) +
                   ", got " + std::to_string(value));
  }
}

void validate_camera(const std::string& file, const Camera& camera) {
  check_finite(file, "camera.eye", camera.eye);
  check_finite(file, "camera.target", camera.target);
  check_finite(file, "camera.up", camera.up);
  if (!(camera.fov_y > 0.0f && camera.fov_y < 180.0f)) {
    fail_field(file, "camera.fov_y",
               "must be between 0 and 180 degrees (exclusive), got " + number_text(camera.fov_y));
  }
  // In double so that the test is exact for any finite float input.
  const glm::dvec3 view = glm::dvec3(camera.target) - glm::dvec3(camera.eye);
  const glm::dvec3 up(camera.up);
  if (glm::length(view) == 0.0) fail_field(file, "camera.target", "must differ from camera.eye");
  if (glm::length(up) == 0.0) fail_field(file, "camera.up", "must not be zero");
  if (glm::length(glm::cross(glm::normalize(view), glm::normalize(up))) < 1e-6) {
    fail_field(file, "camera.up", "must not be parallel to the view direction (target - eye)");
  }
}

void validate_render(const std::string& file, const RenderSettings& render) {
  check_range(file, "render.width", render.width, 1, kMaxImageSide);
  check_range(file, "render.height", render.height, 1, kMaxImageSide);
  const long long pixels = static_cast<long long>(render.width) * render.height;
  if (pixels > kMaxImagePixels) {
    fail_field(file, "render",
               std::to_string(render.width) + "x" + std::to_string(render.height) + " is " +
                   std::to_string(pixels) + " pixels, more than the limit of " +
                   std::to_string(kMaxImagePixels));
  }
  check_range(file, "render.spp", render.spp, 1, kMaxSpp);
}

void validate_material(const std::string& file, const std::string& field, const Material& m) {
  check_colour(file, field + ".ambient", m.ambient);
  check_colour(file, field + ".diffuse", m.diffuse);
  check_colour(file, field + ".specular", m.specular);
  check_colour(file, field + ".emission", m.emission);
  if (!(std::isfinite(m.shininess) && m.shininess >= 0.0f)) {
    fail_field(file, field + ".shininess",
               "must be a finite number >= 0, got " + number_text(m.shininess));
  }
}

void validate_light(const std::string& file, const std::string& field, const PointLight& l) {
  check_finite(file, field + ".position", l.position);
  check_colour(file, field + ".ambient", l.ambient);
  check_colour(file, field + ".diffuse", l.diffuse);
  check_colour(file, field + ".specular", l.specular);
  const glm::vec3& c = l.attenuation;
  check_finite(file, field + ".attenuation", c);
  if (c.x < 0.0f || c.y < 0.0f || c.z < 0.0f || (c.x == 0.0f && c.y == 0.0f && c.z == 0.0f)) {
    fail_field(file, field + ".attenuation",
               "coefficients [c0, c1, c2] must be >= 0 and not all 0");
  }
}

void validate_object(const Scene& scene, std::size_t index) {
  const std::string& file = scene.path;
  const Object& object = scene.objects[index];
  const std::string field = index_path("objects", index);
  if (object.material < 0 || object.material >= static_cast<int>(scene.materials.size())) {
    fail_field(file, field + ".material",
               "material index " + std::to_string(object.material) + " is out of range");
  }
  if (object.type == ObjectType::sphere) {
    check_finite(file, field + ".center", object.center);
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
  validate_camera(file, scene.camera);
  validate_render(file, scene.render);
  check_colour(file, "background", scene.background);
  check_colour(file, "ambient", scene.ambient);
  for (std::size_t i = 0; i < scene.lights.size(); ++i) {
    validate_light(file, index_path("lights", i), scene.lights[i]);
  }
  if (scene.material_names.size() != scene.materials.size()) {
    fail_field(file, "materials", "every material needs a name");
  }
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    validate_material(file, child_path("materials", scene.material_names[i]), scene.materials[i]);
  }
  for (std::size_t i = 0; i < scene.objects.size(); ++i) validate_object(scene, i);
}

}  // namespace gloss
