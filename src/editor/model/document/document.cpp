#include "editor/model/document/document.h"

#include <algorithm>
#include <stdexcept>

#include "io/material/preset_table.h"
#include "scene/fields/fields.h"
#include "scene/fields/scene_diff.h"

namespace gloss {

namespace {
float slider_exponent(float exponent) {
  const Field<Material>& shininess = *find_field(material_fields(), "shininess");
  return std::clamp(exponent, static_cast<float>(shininess.ui_min),
                    static_cast<float>(shininess.ui_max));
}
}  // namespace

float blinn_exponent_for_phong(float phong_exponent) {
  return slider_exponent(4.0f * phong_exponent);
}

float phong_exponent_for_blinn(float blinn_exponent) {
  return slider_exponent(blinn_exponent / 4.0f);
}

float exponent_for_model(float exponent, ShadingModel from, ShadingModel to) {
  if (from == to) return exponent;
  return to == ShadingModel::blinn_phong ? blinn_exponent_for_phong(exponent)
                                         : phong_exponent_for_blinn(exponent);
}

Scene with_model(const Scene& scene, ShadingModel model, bool keep) {
  Scene out = scene;
  if (keep) {
    for (Material& m : out.materials) {
      m.shininess = exponent_for_model(m.shininess, scene.render.model, model);
    }
  }
  out.render.model = model;
  return out;
}

bool same_scene(const Scene& a, const Scene& b) {
  return !diff_scenes(a, b).any;
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
  scene.objects = {sphere_object("gold sphere", {-1.2f, 0.0f, 0.0f}, 1.0f, 0),
                   sphere_object("silver sphere", {1.2f, 0.0f, 0.0f}, 1.0f, 1)};
  scene.render.width = 800;
  scene.render.height = 600;
  scene.render.spp = 4;
  return scene;
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
