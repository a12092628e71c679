#pragma once
// Edits of the scene's objects and of its materials' identities (issue 24): adding, deleting,
// duplicating, hiding and naming objects, moving them (their transforms), naming, assigning and
// copying materials. Plain values like every Command (command.h); apply_command applies them,
// validate_scene checks the result. Object indices name objects as they are before the edit;
// after a delete the later objects' indices shift down.
#include <string>
#include <vector>

#include "scene/scene.h"

namespace gloss {

// Appends objects, and the materials they bring first: material_names[i] / materials[i] join
// the scene's materials at the end, so an object's material index may name an existing
// material or one of these (scene.materials.size() + i). new_objects.h makes them.
struct AddObjects {
  std::vector<Object> objects;  // placed (place_object done)
  std::vector<std::string> material_names;
  std::vector<Material> materials;
  std::string label;  // "add sphere", "add Wuson.ply"
};
struct DeleteObjects {
  std::vector<int> objects;
};
// Copies of the objects after the last one, sharing their materials, moved beside the
// originals (along the camera's right by the selection's width) so they can be seen; named
// "<name> 2", "<name> 3" ...
struct DuplicateObjects {
  std::vector<int> objects;
};
struct SetHidden {
  std::vector<int> objects;
  bool hidden = true;
};
// Shows these objects and hides every other one.
struct SoloObjects {
  std::vector<int> objects;
};
// A new name, unique among the objects and not empty.
struct RenameObject {
  int object = 0;
  std::string name;
};
// The transforms of several objects at once (a gizmo drag of a selection): one undo step per
// drag, whatever it holds (merge key).
struct TransformObjects {
  std::vector<int> objects;
  std::vector<ObjectTransform> transforms;  // parallel to objects
};
// A material's new name: unique among the materials, not empty.
struct RenameMaterial {
  std::string from, to;
};
// Objects use an existing material (reuse).
struct AssignMaterial {
  std::vector<int> objects;
  int material = 0;
};
// A new material (a copy to edit apart, or a library's), added under a unique name made from
// name and given to the objects.
struct NewMaterial {
  std::vector<int> objects;
  Material material;
  std::string name;
};

void apply_object_command(const AddObjects& c, Scene& scene);
void apply_object_command(const DeleteObjects& c, Scene& scene);
void apply_object_command(const DuplicateObjects& c, Scene& scene);
void apply_object_command(const SetHidden& c, Scene& scene);
void apply_object_command(const SoloObjects& c, Scene& scene);
void apply_object_command(const RenameObject& c, Scene& scene);
void apply_object_command(const TransformObjects& c, Scene& scene);
void apply_object_command(const RenameMaterial& c, Scene& scene);
void apply_object_command(const AssignMaterial& c, Scene& scene);
void apply_object_command(const NewMaterial& c, Scene& scene);

// What the Edit menu says ("delete object 2 (ball)", "move 3 objects").
std::string object_command_label(const AddObjects& c);
std::string object_command_label(const DeleteObjects& c);
std::string object_command_label(const DuplicateObjects& c);
std::string object_command_label(const SetHidden& c);
std::string object_command_label(const SoloObjects& c);
std::string object_command_label(const RenameObject& c);
std::string object_command_label(const TransformObjects& c);
std::string object_command_label(const RenameMaterial& c);
std::string object_command_label(const AssignMaterial& c);
std::string object_command_label(const NewMaterial& c);

// One undo step per gesture: transforms of the same objects merge while a drag lasts.
std::string transform_merge_key(const TransformObjects& c);

// The object named name, or -1.
int find_object(const Scene& scene, const std::string& name);
// base, or "base 2", "base 3" ... whichever no object of scene is called.
std::string unique_object_name(const Scene& scene, const std::string& base);
// The same among the material names.
std::string unique_material_name(const Scene& scene, const std::string& base);

}  // namespace gloss
