#include "editor/model/command.h"

#include <cmath>
#include <cstdio>

#include "base/overloaded.h"
#include "io/preset_table.h"

namespace gloss {

namespace {

bool finite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

void check_colour(const glm::vec3& v, const std::string& what) {
  if (!finite(v) || v.x < 0.0f || v.y < 0.0f || v.z < 0.0f) {
    throw CommandError(what + " must be finite and not negative");
  }
}

Material& object_material(Scene& scene, int object) {
  if (object < 0 || object >= static_cast<int>(scene.objects.size())) {
    throw CommandError("no object " + std::to_string(object) + " (the scene has " +
                       std::to_string(scene.objects.size()) + ")");
  }
  const int material = scene.objects[object].material;
  if (material < 0 || material >= static_cast<int>(scene.materials.size())) {
    throw CommandError("object " + std::to_string(object) + " has no valid material");
  }
  return scene.materials[material];
}

PointLight& scene_light(Scene& scene, int light) {
  if (light < 0 || light >= static_cast<int>(scene.lights.size())) {
    throw CommandError("no light " + std::to_string(light) + " (the scene has " +
                       std::to_string(scene.lights.size()) + ")");
  }
  return scene.lights[light];
}

void check_light_value(LightField field, const glm::vec3& v) {
  if (field == LightField::position) {
    if (!finite(v)) throw CommandError("light position must be finite");
    return;
  }
  check_colour(v, std::string("light ") + to_string(field));
  if (field == LightField::attenuation && v == glm::vec3(0.0f)) {
    throw CommandError("attenuation coefficients must not all be zero");
  }
}

void check_camera(const Camera& camera) {
  if (!finite(camera.eye) || !finite(camera.target) || !finite(camera.up) ||
      !(camera.fov_y > 0.0f && camera.fov_y < 180.0f)) {
    throw CommandError("camera values must be finite with 0 < fov_y < 180");
  }
  try {
    make_camera_frame(camera, 1, 1);
  } catch (const std::exception& e) {
    throw CommandError(std::string("camera: ") + e.what());
  }
}

std::string vec_text(const glm::vec3& v) {
  char text[96];
  std::snprintf(text, sizeof text, "(%g, %g, %g)", v.x, v.y, v.z);
  return text;
}

}  // namespace

void apply_command(const Command& command, Scene& scene) {
  // Work on a copy so a throw leaves the document as it was.
  Scene next = scene;
  std::visit(
      Overloaded{
          [&](const SetMaterialColour& c) {
            if (c.field == MaterialField::shininess) throw CommandError("shininess is a number");
            check_colour(c.value, to_string(c.field));
            Material& m = object_material(next, c.object);
            material_colour(m, c.field) = c.value;
          },
          [&](const SetShininess& c) {
            // The spec's range of alpha; the slider offers 0..kMaxShininess.
            if (!std::isfinite(c.value) || c.value < 0.0f || c.value > 1e6f) {
              throw CommandError("shininess must be between 0 and 1e6");
            }
            object_material(next, c.object).shininess = c.value;
          },
          [&](const ApplyPreset& c) {
            const Preset* preset = find_preset(c.name);
            if (preset == nullptr) {
              std::string message = "unknown preset '" + c.name + "'";
              const auto near = nearest_preset_names(c.name, 1);
              if (!near.empty()) message += " (did you mean '" + near.front() + "'?)";
              throw CommandError(message);
            }
            object_material(next, c.object) = preset->material;
          },
          [&](const SetMaterial& c) {
            for (MaterialField f : {MaterialField::ambient, MaterialField::diffuse,
                                    MaterialField::specular, MaterialField::emission}) {
              check_colour(material_colour(c.material, f), to_string(f));
            }
            if (!std::isfinite(c.material.shininess) || c.material.shininess < 0.0f) {
              throw CommandError("shininess must be finite and not negative");
            }
            object_material(next, c.object) = c.material;
          },
          [&](const SetModel& c) {
            if (c.keep_highlight_size) {
              for (Material& m : next.materials) {
                m.shininess = exponent_for_model(m.shininess, next.render.model, c.model);
              }
            }
            next.render.model = c.model;
          },
          [&](const SetEnergyNormalize& c) { next.render.energy_normalize = c.on; },
          [&](const SetLightValue& c) {
            check_light_value(c.field, c.value);
            light_value(scene_light(next, c.light), c.field) = c.value;
          },
          [&](const AddLight& c) {
            for (LightField f : {LightField::position, LightField::ambient, LightField::diffuse,
                                 LightField::specular, LightField::attenuation}) {
              check_light_value(f, light_value(c.light, f));
            }
            next.lights.push_back(c.light);
          },
          [&](const RemoveLight& c) {
            scene_light(next, c.light);
            next.lights.erase(next.lights.begin() + c.light);
          },
          [&](const SetSceneAmbient& c) {
            check_colour(c.value, "scene ambient");
            next.ambient = c.value;
          },
          [&](const SetBackground& c) {
            check_colour(c.value, "background");
            next.background = c.value;
          },
          [&](const SetShadows& c) { next.render.shadows = c.on; },
          [&](const SetCamera& c) {
            check_camera(c.camera);
            next.camera = c.camera;
          },
          [&](const OrbitCamera& c) {
            if (!std::isfinite(c.yaw_deg) || !std::isfinite(c.pitch_deg)) {
              throw CommandError("orbit angles must be finite");
            }
            const Camera camera = orbit_camera(next.camera, c.yaw_deg, c.pitch_deg);
            check_camera(camera);
            next.camera = camera;
          },
          [&](const SetTargetSpp& c) {
            if (c.spp < 1 || c.spp > kMaxSpp) {
              throw CommandError("target spp must be between 1 and " + std::to_string(kMaxSpp));
            }
            next.render.spp = c.spp;
          },
          [&](const ReplaceScene& c) {
            if (!c.scene) throw CommandError("no scene to open");
            next = *c.scene;
          },
      },
      command);
  scene = std::move(next);
}

std::string command_label(const Command& command) {
  return std::visit(
      Overloaded{
          [](const SetMaterialColour& c) {
            return std::string("set ") + to_string(c.field) + " of object " +
                   std::to_string(c.object) + " to " + vec_text(c.value);
          },
          [](const SetShininess& c) {
            char text[32];
            std::snprintf(text, sizeof text, "%g", c.value);
            return "set shininess of object " + std::to_string(c.object) + " to " + text;
          },
          [](const ApplyPreset& c) {
            return "apply preset " + c.name + " to object " + std::to_string(c.object);
          },
          [](const SetMaterial& c) {
            return "load material " + c.source + " into object " + std::to_string(c.object);
          },
          [](const SetModel& c) {
            return std::string("switch to ") + to_string(c.model) +
                   (c.keep_highlight_size ? " (keep highlight size)" : "");
          },
          [](const SetEnergyNormalize& c) {
            return std::string("turn energy normalisation ") + (c.on ? "on" : "off");
          },
          [](const SetLightValue& c) {
            if (c.field == LightField::position) return "move light " + std::to_string(c.light);
            return std::string("set ") + to_string(c.field) + " of light " +
                   std::to_string(c.light);
          },
          [](const AddLight&) { return std::string("add light"); },
          [](const RemoveLight& c) { return "remove light " + std::to_string(c.light); },
          [](const SetSceneAmbient&) { return std::string("set scene ambient"); },
          [](const SetBackground&) { return std::string("set background"); },
          [](const SetShadows& c) { return std::string("turn shadows ") + (c.on ? "on" : "off"); },
          [](const SetCamera&) { return std::string("move camera"); },
          [](const OrbitCamera&) { return std::string("orbit camera"); },
          [](const SetTargetSpp& c) { return "set target spp to " + std::to_string(c.spp); },
          [](const ReplaceScene& c) { return c.label; },
      },
      command);
}

std::string merge_key(const Command& command) {
  return std::visit(
      Overloaded{
          [](const SetMaterialColour& c) {
            return "colour " + std::to_string(c.object) + " " + to_string(c.field);
          },
          [](const SetShininess& c) { return "shininess " + std::to_string(c.object); },
          [](const SetLightValue& c) {
            return "light " + std::to_string(c.light) + " " + to_string(c.field);
          },
          [](const SetSceneAmbient&) { return std::string("scene ambient"); },
          [](const SetBackground&) { return std::string("background"); },
          [](const SetCamera&) { return std::string("camera"); },
          [](const SetTargetSpp&) { return std::string("spp"); },
          [](const auto&) { return std::string(); },
      },
      command);
}

}  // namespace gloss
