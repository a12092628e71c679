#pragma once
// Edits of the document. Panels, the viewport and scripts build these; the command layer applies
// them and records undo steps. Each command is a plain value: what to change and to what.
#include <memory>
#include <stdexcept>
#include <string>
#include <variant>

#include "editor/model/document.h"

namespace gloss {

// A command that cannot apply (bad index, negative colour, unknown preset); what() says why.
class CommandError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Objects are named by index; a command edits the material the object uses (shared materials
// change on every object that uses them).
struct SetMaterialColour {
  int object = 0;
  MaterialField field = MaterialField::diffuse;  // not shininess
  glm::vec3 value{0.0f};                         // linear RGB, >= 0
};
struct SetShininess {
  int object = 0;
  float value = 32.0f;  // Phong exponent, 0..kMaxShininess
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
struct SetModel {
  ShadingModel model = ShadingModel::phong;
  bool keep_highlight_size = false;  // rescale every exponent (document.h's rule)
};
struct SetEnergyNormalize {
  bool on = false;
};
struct SetLightValue {
  int light = 0;
  LightField field = LightField::position;
  glm::vec3 value{0.0f};  // world units for position; colours >= 0; attenuation >= 0, not all 0
};
struct AddLight {
  PointLight light;
};
struct RemoveLight {
  int light = 0;
};
struct SetSceneAmbient {
  glm::vec3 value{0.0f};  // A_scene, >= 0
};
struct SetBackground {
  glm::vec3 value{0.0f};
};
struct SetShadows {
  bool on = true;
};
struct SetCamera {
  Camera camera;
};
// Orbits the current camera about its target (camera.h's orbit_camera), degrees.
struct OrbitCamera {
  float yaw_deg = 0.0f;
  float pitch_deg = 0.0f;
};
struct SetTargetSpp {
  int spp = 1;  // 1..kMaxSpp
};
// Replaces the whole document (open a scene, add an OBJ file's objects).
struct ReplaceScene {
  std::shared_ptr<const Scene> scene;
  std::string label;
};

using Command =
    std::variant<SetMaterialColour, SetShininess, ApplyPreset, SetMaterial, SetModel,
                 SetEnergyNormalize, SetLightValue, AddLight, RemoveLight, SetSceneAmbient,
                 SetBackground, SetShadows, SetCamera, OrbitCamera, SetTargetSpp, ReplaceScene>;

// Applies command to scene. Throws CommandError naming the bad argument; scene is then unchanged.
void apply_command(const Command& command, Scene& scene);

// What the Edit menu says: "Undo set diffuse of object 0".
std::string command_label(const Command& command);

// Commands with the same non-empty key coalesce into one undo step while a gesture lasts (a
// slider drag, a camera drag, the light animation); see CommandLayer::seal.
std::string merge_key(const Command& command);

}  // namespace gloss
