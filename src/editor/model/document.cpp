#include "editor/model/document.h"

#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include "io/preset_table.h"

namespace gloss {

const char* to_string(MaterialField field) {
  switch (field) {
    case MaterialField::ambient:
      return "ambient";
    case MaterialField::diffuse:
      return "diffuse";
    case MaterialField::specular:
      return "specular";
    case MaterialField::emission:
      return "emission";
    case MaterialField::shininess:
      return "shininess";
  }
  return "?";
}

bool parse_material_field(const std::string& name, MaterialField& field) {
  for (MaterialField f : {MaterialField::ambient, MaterialField::diffuse, MaterialField::specular,
                          MaterialField::emission, MaterialField::shininess}) {
    if (name == to_string(f)) {
      field = f;
      return true;
    }
  }
  return false;
}

glm::vec3& material_colour(Material& material, MaterialField field) {
  switch (field) {
    case MaterialField::ambient:
      return material.ambient;
    case MaterialField::diffuse:
      return material.diffuse;
    case MaterialField::specular:
      return material.specular;
    case MaterialField::emission:
      return material.emission;
    case MaterialField::shininess:
      break;
  }
  throw std::invalid_argument("shininess is not a colour");
}

const glm::vec3& material_colour(const Material& material, MaterialField field) {
  return material_colour(const_cast<Material&>(material), field);
}

const char* to_string(LightField field) {
  switch (field) {
    case LightField::position:
      return "position";
    case LightField::ambient:
      return "ambient";
    case LightField::diffuse:
      return "diffuse";
    case LightField::specular:
      return "specular";
    case LightField::attenuation:
      return "attenuation";
  }
  return "?";
}

bool parse_light_field(const std::string& name, LightField& field) {
  for (LightField f : {LightField::position, LightField::ambient, LightField::diffuse,
                       LightField::specular, LightField::attenuation}) {
    if (name == to_string(f)) {
      field = f;
      return true;
    }
  }
  return false;
}

glm::vec3& light_value(PointLight& light, LightField field) {
  switch (field) {
    case LightField::position:
      return light.position;
    case LightField::ambient:
      return light.ambient;
    case LightField::diffuse:
      return light.diffuse;
    case LightField::specular:
      return light.specular;
    case LightField::attenuation:
      return light.attenuation;
  }
  return light.position;
}

const glm::vec3& light_value(const PointLight& light, LightField field) {
  return light_value(const_cast<PointLight&>(light), field);
}

float blinn_exponent_for_phong(float phong_exponent) {
  return std::clamp(4.0f * phong_exponent, 0.0f, kMaxShininess);
}

float phong_exponent_for_blinn(float blinn_exponent) {
  return std::clamp(blinn_exponent / 4.0f, 0.0f, kMaxShininess);
}

float exponent_for_model(float exponent, ShadingModel from, ShadingModel to) {
  if (from == to) return exponent;
  return to == ShadingModel::blinn_phong ? blinn_exponent_for_phong(exponent)
                                         : phong_exponent_for_blinn(exponent);
}

namespace {

bool same_render(const RenderSettings& a, const RenderSettings& b) {
  return a.width == b.width && a.height == b.height && a.spp == b.spp && a.model == b.model &&
         a.shadows == b.shadows && a.energy_normalize == b.energy_normalize && a.srgb == b.srgb &&
         a.seed == b.seed && a.pow == b.pow;
}

bool same_object(const Object& a, const Object& b) {
  return a.name == b.name && a.type == b.type && a.material == b.material && a.center == b.center &&
         a.radius == b.radius && a.mesh == b.mesh && a.params.file == b.params.file &&
         a.params.group == b.params.group && a.params.position == b.params.position &&
         a.params.scale == b.params.scale && a.params.rotate_y == b.params.rotate_y;
}

}  // namespace

bool same_scene(const Scene& a, const Scene& b) {
  return a.camera == b.camera && a.background == b.background && a.ambient == b.ambient &&
         a.lights == b.lights && a.materials == b.materials &&
         a.material_names == b.material_names && same_render(a.render, b.render) &&
         a.path == b.path && a.objects.size() == b.objects.size() &&
         std::equal(a.objects.begin(), a.objects.end(), b.objects.begin(), same_object);
}

Scene builtin_scene() {
  Scene scene;
  scene.camera.eye = {0.0f, 0.6f, 6.0f};
  scene.camera.target = {0.0f, 0.0f, 0.0f};
  scene.camera.fov_y = 35.0f;
  scene.ambient = glm::vec3(0.2f);
  PointLight light;
  light.position = {4.0f, 4.0f, 5.0f};
  scene.lights.push_back(light);
  for (const char* name : {"gold", "silver"}) {
    const Preset* preset = find_preset(name);
    if (preset == nullptr) throw std::runtime_error(std::string("no preset named ") + name);
    scene.materials.push_back(preset->material);
    scene.material_names.push_back(name);
  }
  Object gold;
  gold.name = "gold sphere";
  gold.center = {-1.2f, 0.0f, 0.0f};
  gold.material = 0;
  Object silver;
  silver.name = "silver sphere";
  silver.center = {1.2f, 0.0f, 0.0f};
  silver.material = 1;
  scene.objects = {gold, silver};
  scene.render.width = 800;
  scene.render.height = 600;
  scene.render.spp = 4;
  return scene;
}

void move_document(Scene& scene, const std::string& path) {
  namespace fs = std::filesystem;
  const fs::path old_folder = fs::path(scene.path).parent_path();
  const fs::path new_folder = fs::path(path).parent_path();
  for (Object& object : scene.objects) {
    std::string& file = object.params.file;
    if (file.empty() || fs::path(file).is_absolute()) continue;
    std::error_code ec;
    const fs::path target = fs::absolute(old_folder / file, ec).lexically_normal();
    const fs::path base = fs::absolute(new_folder, ec).lexically_normal();
    const fs::path relative = target.lexically_relative(base);
    file = relative.empty() ? target.string() : relative.string();
  }
  scene.path = path;
}

std::string object_label(const Scene& scene, int object) {
  std::string label = "object " + std::to_string(object);
  if (object >= 0 && object < static_cast<int>(scene.objects.size()) &&
      !scene.objects[object].name.empty()) {
    label += " (" + scene.objects[object].name + ")";
  }
  return label;
}

}  // namespace gloss
