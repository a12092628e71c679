#include "editor/model/document/command.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "base/assets.h"
#include "base/error.h"
#include "base/overloaded.h"
#include "base/text/text_distance.h"
#include "io/material/preset_table.h"
#include "io/scene/environment_reader.h"
#include "io/scene/material_maps.h"
#include "io/scene/scene_files.h"
#include "io/scene/scene_loader.h"
#include "scene/fields/validation.h"
#include "scene/geometry/placement.h"

namespace gloss {

namespace {

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

PhysicalReference& object_reference(Scene& scene, int object) {
  Material& m = object_material(scene, object);
  if (!m.reference) {
    throw CommandError("object " + std::to_string(object) +
                       "'s material has no physical reference (give it one first)");
  }
  return *m.reference;
}

Object& scene_object(Scene& scene, int object) {
  if (object < 0 || object >= static_cast<int>(scene.objects.size())) {
    throw CommandError("no object " + std::to_string(object) + " (the scene has " +
                       std::to_string(scene.objects.size()) + ")");
  }
  return scene.objects[static_cast<std::size_t>(object)];
}

PointLight& scene_light(Scene& scene, int light) {
  if (light < 0 || light >= static_cast<int>(scene.lights.size())) {
    throw CommandError("no light " + std::to_string(light) + " (the scene has " +
                       std::to_string(scene.lights.size()) + ")");
  }
  return scene.lights[light];
}

template <class S>
const Field<S>& table_field(const FieldTable<S>& table, FieldPart part, const std::string& key) {
  const Field<S>* field = find_field(table, key);
  if (field == nullptr) {
    throw CommandError(std::string("no ") + to_string(part) + " field '" + key + "'" +
                       did_you_mean(nearest_words(key, field_keys(table), 1)));
  }
  return *field;
}

// The value is checked with the field's own rule before the setter converts it: the conversion
// to the member's type (int, float) is undefined outside its range, so validating the scene
// afterwards is too late (`render height 1e400` from a script; found by fuzz/fuzz_script).
template <class S>
void set_in(const FieldTable<S>& table, FieldPart part, S& target, const SetField& c) {
  const Field<S>& field = table_field(table, part, c.key);
  const FieldProblem problem = field_problem(field, c.value);
  if (!problem.message.empty()) {
    throw CommandError(std::string(to_string(part)) + " " + c.key + ": " + problem.message);
  }
  field.set(target, c.value);
}

// A map named by its file (a script line, the load button) is read here, against the scene's
// folder, so the document only ever holds maps with their textures.
SetField with_map_read(const SetField& c, const Scene& scene) {
  MapSlot slot;
  if (c.part != FieldPart::material || !map_slot_of_key(c.key, slot)) return c;
  SetField read = c;
  MapReadContext context;
  context.file = scene.path;
  context.base_dir = std::filesystem::path(scene.path).parent_path().string();
  try {
    read_map(read.value.map, slot, context);
  } catch (const InputError& error) {
    throw CommandError(c.key + ": " + error.what());
  }
  return read;
}

void set_field(const SetField& c, Scene& scene) {
  switch (c.part) {
    case FieldPart::material:
      return set_in(material_fields(), c.part, object_material(scene, c.index),
                    with_map_read(c, scene));
    case FieldPart::light:
      return set_in(light_fields(), c.part, scene_light(scene, c.index), c);
    case FieldPart::render:
      return set_in(render_fields(), c.part, scene.render, c);
    case FieldPart::camera:
      return set_in(camera_fields(), c.part, scene.camera, c);
    case FieldPart::scene:
      return set_in(scene_fields(), c.part, scene, c);
    case FieldPart::reference:
      return set_in(reference_fields(), c.part, object_reference(scene, c.index), c);
    case FieldPart::transform: {
      Object& object = scene_object(scene, c.index);
      set_in(transform_fields(), c.part, object.transform, c);
      return place_object(object);
    }
    case FieldPart::object:
      return set_in(object_fields(), c.part, scene_object(scene, c.index), c);
    case FieldPart::environment:
      if (!scene.environment.present()) {
        throw CommandError("the scene has no environment light (give it a map first)");
      }
      return set_in(environment_fields(), c.part, scene.environment, c);
  }
}

// The field's label and its value as text, for undo labels.
template <class S>
std::string describe(const FieldTable<S>& table, const SetField& c) {
  const Field<S>* field = find_field(table, c.key);
  if (field == nullptr) return c.key;
  return std::string(field->label) + " to " + field_text(*field, c.value);
}

std::string describe(const SetField& c) {
  switch (c.part) {
    case FieldPart::material:
      return describe(material_fields(), c) + " (object " + std::to_string(c.index) + ")";
    case FieldPart::light:
      return describe(light_fields(), c) + " (light " + std::to_string(c.index) + ")";
    case FieldPart::render:
      return describe(render_fields(), c);
    case FieldPart::camera:
      return "camera " + describe(camera_fields(), c);
    case FieldPart::scene:
      return describe(scene_fields(), c);
    case FieldPart::reference:
      return "reference " + describe(reference_fields(), c) + " (object " +
             std::to_string(c.index) + ")";
    case FieldPart::transform:
      return describe(transform_fields(), c) + " (object " + std::to_string(c.index) + ")";
    case FieldPart::object:
      return describe(object_fields(), c) + " (object " + std::to_string(c.index) + ")";
    case FieldPart::environment:
      return "environment " + describe(environment_fields(), c);
  }
  return c.key;
}

// Whether edits of the field come as gestures (a drag of a slider, a colour or a vector) that
// make one undo step, or one by one (flags and choices: a click each).
bool continuous(const SetField& c) {
  auto of = [&](const auto& table) {
    const auto* field = find_field(table, c.key);
    return field != nullptr && field->kind != FieldKind::flag && field->kind != FieldKind::choice &&
           field->kind != FieldKind::map;
  };
  switch (c.part) {
    case FieldPart::material:
      return of(material_fields());
    case FieldPart::light:
      return of(light_fields());
    case FieldPart::render:
      return of(render_fields());
    case FieldPart::camera:
      return of(camera_fields());
    case FieldPart::scene:
      return of(scene_fields());
    case FieldPart::reference:
      return of(reference_fields());
    case FieldPart::transform:
      return of(transform_fields());
    case FieldPart::object:
      return of(object_fields());
    case FieldPart::environment:
      return of(environment_fields());
  }
  return false;
}

// Every teapot re-tessellated in place (io/scene/scene_object_reader.h's teapot_mesh, the reader's
// own construction); the other objects keep their shared meshes.
void set_tessellation(int level, Scene& scene) {
  if (level < 1 || level > 64) {
    throw CommandError("tessellation " + std::to_string(level) + " is outside 1..64");
  }
  bool any = false;
  for (Object& o : scene.objects) {
    if (o.type != ObjectType::teapot) continue;
    any = true;
    if (o.params.tessellation == level) continue;
    o.params.tessellation = level;
    o.shape = std::make_shared<const Mesh>(teapot_mesh(o.params));
    place_object(o);
  }
  if (!any) throw CommandError("the scene has no teapot to tessellate");
}

// The map of a SetEnvironment read into scene's environment (file: scene/environment.h's
// `file`, relative to the scene's folder when the scene has one).
void set_environment(const SetEnvironment& c, Scene& scene) {
  namespace fs = std::filesystem;
  if (c.file.empty()) {
    scene.environment.map = nullptr;
    scene.environment.file.clear();
    return;
  }
  const fs::path scene_folder =
      scene.path.empty() ? fs::path() : fs::path(scene.path).parent_path();
  fs::path path(c.file);
  std::error_code error;
  const std::vector<std::string>& shipped = shipped_environments();
  if (std::find(shipped.begin(), shipped.end(), c.file) != shipped.end()) {
    path = asset_path("environments/" + c.file + ".exr");
  } else if (!path.is_absolute() && !fs::exists(path, error) && !scene_folder.empty()) {
    path = scene_folder / path;
  }
  try {
    scene.environment.map = read_environment_map(path.string());
  } catch (const InputError& e) {
    throw CommandError(e.what());
  }
  scene.environment.file = name_for_scene(path.string(), scene.path);
}

}  // namespace

const std::vector<std::string>& shipped_environments() {
  static const std::vector<std::string> names = {"studio", "sunset", "city"};
  return names;
}

std::string reference_text(const PhysicalReference& r) {
  char text[96];
  if (is_metal(r.kind)) {
    std::snprintf(text, sizeof text, "%s r %g", to_string(r.kind), r.roughness);
  } else {
    std::snprintf(text, sizeof text, "dielectric %g %g %g r %g", r.base.x, r.base.y, r.base.z,
                  r.roughness);
  }
  return text;
}

const char* to_string(FieldPart part) {
  switch (part) {
    case FieldPart::material:
      return "material";
    case FieldPart::light:
      return "light";
    case FieldPart::render:
      return "render";
    case FieldPart::camera:
      return "camera";
    case FieldPart::scene:
      return "scene";
    case FieldPart::reference:
      return "reference";
    case FieldPart::transform:
      return "transform";
    case FieldPart::object:
      return "object";
    case FieldPart::environment:
      return "environment";
  }
  return "?";
}

void apply_command(const Command& command, Scene& scene) {
  // Work on a copy so a throw leaves the document as it was.
  Scene next = scene;
  std::visit(
      Overloaded{
          [&](const SetField& c) { set_field(c, next); },
          [&](const ApplyPreset& c) {
            const Preset* preset = find_preset(c.name);
            if (preset == nullptr) {
              throw CommandError("unknown preset '" + c.name + "'" +
                                 did_you_mean(nearest_preset_names(c.name, 1)));
            }
            // The preset's constants; the maps stay (docs/spec/shading.md, "Textures").
            Material& material = object_material(next, c.object);
            material = with_constants(material, preset->material);
          },
          [&](const SetMaterial& c) { object_material(next, c.object) = c.material; },
          [&](const SetModel& c) {
            if (c.keep_highlight_size) {
              for (Material& m : next.materials) {
                m.shininess = exponent_for_model(m.shininess, next.render.model, c.model);
              }
            }
            next.render.model = c.model;
          },
          [&](const AddLight& c) { next.lights.push_back(c.light); },
          [&](const RemoveLight& c) {
            scene_light(next, c.light);
            next.lights.erase(next.lights.begin() + c.light);
          },
          [&](const SetCamera& c) { next.camera = c.camera; },
          [&](const OrbitCamera& c) {
            if (!std::isfinite(c.yaw_deg) || !std::isfinite(c.pitch_deg)) {
              throw CommandError("orbit angles must be finite");
            }
            next.camera = orbit_camera(next.camera, c.yaw_deg, c.pitch_deg);
          },
          [&](const SetTessellation& c) { set_tessellation(c.level, next); },
          [&](const ReplaceScene& c) {
            if (!c.scene) throw CommandError("no scene to open");
            next = *c.scene;
          },
          [&](const SetReference& c) { object_material(next, c.object).reference = c.reference; },
          [&](const ApplyFit& c) {
            object_material(next, c.object) = c.material;
            if (c.model) next.render.model = *c.model;
          },
          [&](const SetEnvironment& c) { set_environment(c, next); },
          [&](const auto& c) { apply_object_command(c, next); },  // object_commands.h
      },
      command);
  try {
    validate_scene(next, SampleMemory::whole_image);  // the progressive renderer holds it all
  } catch (const InputError& e) {
    throw CommandError(e.field().empty() ? e.message() : e.field() + ": " + e.message());
  }
  scene = std::move(next);
}

std::string command_label(const Command& command) {
  return std::visit(
      Overloaded{
          [](const SetField& c) {
            if (c.part == FieldPart::light && c.key == "position") {
              return "move light " + std::to_string(c.index);
            }
            return "set " + describe(c);
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
          [](const AddLight&) { return std::string("add light"); },
          [](const RemoveLight& c) { return "remove light " + std::to_string(c.light); },
          [](const SetCamera&) { return std::string("move camera"); },
          [](const OrbitCamera&) { return std::string("orbit camera"); },
          [](const SetTessellation& c) {
            return "set teapot tessellation to " + std::to_string(c.level);
          },
          [](const ReplaceScene& c) { return c.label; },
          [](const SetReference& c) {
            if (!c.reference) return "remove the reference of object " + std::to_string(c.object);
            return "set the reference of object " + std::to_string(c.object) + " to " +
                   reference_text(*c.reference);
          },
          [](const ApplyFit& c) { return c.label + " (object " + std::to_string(c.object) + ")"; },
          [](const SetEnvironment& c) {
            return c.file.empty() ? std::string("remove the environment")
                                  : "set the environment to " + c.file;
          },
          [](const auto& c) { return object_command_label(c); },  // object_commands.h
      },
      command);
}

std::string merge_key(const Command& command) {
  return std::visit(
      Overloaded{
          [](const SetField& c) {
            if (!continuous(c)) return std::string();
            return std::string(to_string(c.part)) + " " + std::to_string(c.index) + " " + c.key;
          },
          [](const SetCamera&) { return std::string("camera"); },
          // Dragging the panel's roughness or base colour is one undo step.
          [](const SetReference& c) {
            return c.reference ? "reference " + std::to_string(c.object) : std::string();
          },
          // A slider drag through the levels is one undo step.
          [](const SetTessellation&) { return std::string("tessellation"); },
          [](const TransformObjects& c) { return transform_merge_key(c); },
          [](const auto&) { return std::string(); },
      },
      command);
}

}  // namespace gloss
