#pragma once
// Edits of the document. Panels, the viewport and scripts build these; the command layer applies
// them and records undo steps. Each command is a plain value: what to change and to what.
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "editor/model/document/document.h"
#include "editor/model/document/object_commands.h"
#include "scene/fields/fields.h"

namespace gloss {

// A command that cannot apply (bad index, negative colour, unknown preset); what() says why.
class CommandError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The struct a field edit targets, and how SetField::index names it.
enum class FieldPart {
  material,     // the material object `index` uses (shared materials change on every user)
  light,        // light `index`
  render,       // the render settings
  camera,       // the camera
  scene,        // the scene's own fields: background, ambient
  reference,    // the physical reference of the material object `index` uses (it must have one)
  transform,    // object `index`'s transform (translate, rotate, scale, pivot)
  object,       // object `index`'s own fields (hidden)
  environment,  // the environment light's numbers (intensity, rotation, as_background)
};
const char* to_string(FieldPart part);

// Sets one field of a table of scene/fields/fields.h. The value is checked by the document's one
// validator (scene/fields/validation.h) after it is set.
struct SetField {
  FieldPart part = FieldPart::material;
  int index = 0;    // object or light; unused for the other parts
  std::string key;  // a key of the part's table
  FieldValue value;
};
// Loads a preset's constants; with the preset the material already names, this is "reset".
struct ApplyPreset {
  int object = 0;
  std::string name;
};
// Replaces an object's material constants (a material loaded from a file).
struct SetMaterial {
  int object = 0;
  Material material;
  std::string source;  // shown in the undo label, e.g. the material's name
};
// Gives the material object `object` uses a physical reference (docs/spec/physical-reference.md),
// replaces it, or with none removes it.
struct SetReference {
  int object = 0;
  std::optional<PhysicalReference> reference;
};
// A fit's result (editor/model/document/reference_fit.h) in one undo step: the material of
// `object` replaced (its kd, ks and alpha fitted, the rest kept) and, when set, the scene's
// shading model switched to the model the constants were fitted for (no exponent rescaled).
struct ApplyFit {
  int object = 0;
  Material material;
  std::optional<ShadingModel> model;
  std::string label;  // "fit Phong to gold r 0.2"
};
// The model switch of the whole scene, optionally rescaling every exponent (document.h's rule).
struct SetModel {
  ShadingModel model = ShadingModel::phong;
  bool keep_highlight_size = false;
};
struct AddLight {
  PointLight light;
};
struct RemoveLight {
  int light = 0;
};
struct SetCamera {
  Camera camera;
};
// Gives the scene the environment map `file` (read when the command applies: a path, relative to
// the working folder or else to the scene's folder, or a shipped map's name such as "studio"),
// keeping intensity, rotation and background; an empty file removes the environment light.
struct SetEnvironment {
  std::string file;
};
// Orbits the current camera about its target (camera.h's orbit_camera), degrees.
struct OrbitCamera {
  float yaw_deg = 0.0f;
  float pitch_deg = 0.0f;
};
// Re-tessellates every teapot of the document at level segments per patch side (1..64): the
// mesh resolution, the companion knob of the raster path's per-vertex shading.
struct SetTessellation {
  int level = 8;
};
// Replaces the whole document (open a scene, add an OBJ file's objects).
struct ReplaceScene {
  std::shared_ptr<const Scene> scene;
  std::string label;
};

using Command =
    std::variant<SetField, ApplyPreset, SetMaterial, SetModel, AddLight, RemoveLight, SetCamera,
                 OrbitCamera, SetTessellation, ReplaceScene, SetReference, ApplyFit,
                 // objects and material identities (object_commands.h)
                 AddObjects, DeleteObjects, DuplicateObjects, SetHidden, SoloObjects, RenameObject,
                 TransformObjects, RenameMaterial, AssignMaterial, NewMaterial,
                 // the environment light's map
                 SetEnvironment>;

// Applies command to scene and validates the result (scene/fields/validation.h, the document's one
// validator). Throws CommandError naming the bad argument or field; scene is then unchanged.
void apply_command(const Command& command, Scene& scene);

// The command for an edited copy of a part: the first field of table whose value differs, or
// nothing. Panels edit copies with the tables' widgets and hand the change over here.
template <class S>
std::optional<Command> field_command(FieldPart part, int index, const FieldTable<S>& table,
                                     const S& before, const S& after) {
  for (const Field<S>& f : table) {
    const FieldValue value = f.get(after);
    if (value != f.get(before)) return Command(SetField{part, index, f.key, value});
  }
  return std::nullopt;
}

// The shipped environment maps (assets/environments/NAME.exr), by name: studio, sunset, city.
const std::vector<std::string>& shipped_environments();

// A reference as labels and scripts write it: "gold r 0.2", "dielectric 0.6 0.1 0.1 r 0.5".
std::string reference_text(const PhysicalReference& reference);

// What the Edit menu says: "Undo set diffuse of object 0".
std::string command_label(const Command& command);

// Commands with the same non-empty key coalesce into one undo step while a gesture lasts (a
// slider drag, a camera drag, the light animation); see CommandLayer::seal.
std::string merge_key(const Command& command);

}  // namespace gloss
