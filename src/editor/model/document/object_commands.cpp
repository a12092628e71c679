#include "editor/model/document/object_commands.h"

#include <algorithm>
#include <limits>

#include <glm/geometric.hpp>

#include "editor/model/document/command.h"
#include "scene/geometry/placement.h"

namespace gloss {

namespace {

// The indices, each naming an object of scene, sorted, without repeats; at least one.
std::vector<int> checked_objects(const Scene& scene, std::vector<int> objects) {
  if (objects.empty()) throw CommandError("no object given");
  const int count = static_cast<int>(scene.objects.size());
  for (int i : objects) {
    if (i < 0 || i >= count) {
      throw CommandError("no object " + std::to_string(i) + " (the scene has " +
                         std::to_string(count) + ")");
    }
  }
  std::sort(objects.begin(), objects.end());
  objects.erase(std::unique(objects.begin(), objects.end()), objects.end());
  return objects;
}

std::string count_text(std::size_t n, const std::vector<int>& objects) {
  return n == 1 ? "object " + std::to_string(objects.front()) : std::to_string(n) + " objects";
}

std::string numbered(const std::string& base, int n) {
  return n < 2 ? base : base + " " + std::to_string(n);
}

// "ball 3" -> "ball": duplicates of a duplicate count on from the original's name.
std::string name_stem(const std::string& name) {
  const std::size_t space = name.find_last_of(' ');
  if (space == std::string::npos || space + 1 == name.size()) return name;
  const std::string tail = name.substr(space + 1);
  const bool digits =
      std::all_of(tail.begin(), tail.end(), [](char c) { return c >= '0' && c <= '9'; });
  return digits && space > 0 ? name.substr(0, space) : name;
}

// The camera's right, horizontal where it can be.
glm::vec3 camera_right(const Camera& camera) {
  const glm::vec3 forward = glm::normalize(camera.target - camera.eye);
  const glm::vec3 right = glm::cross(forward, camera.up);
  const float length = glm::length(right);
  return length > 0.0f ? right / length : glm::vec3(1.0f, 0.0f, 0.0f);
}

}  // namespace

int find_object(const Scene& scene, const std::string& name) {
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    if (scene.objects[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

std::string unique_object_name(const Scene& scene, const std::string& base) {
  const std::string stem = base.empty() ? std::string("object") : base;
  for (int n = 1;; ++n) {
    if (find_object(scene, numbered(stem, n)) < 0) return numbered(stem, n);
  }
}

std::string unique_material_name(const Scene& scene, const std::string& base) {
  const std::string stem = base.empty() ? std::string("material") : base;
  for (int n = 1;; ++n) {
    if (find_material(scene, numbered(stem, n)) < 0) return numbered(stem, n);
  }
}

void apply_object_command(const AddObjects& c, Scene& scene) {
  if (c.objects.empty()) throw CommandError("nothing to add");
  if (c.material_names.size() != c.materials.size()) {
    throw CommandError("every added material needs a name");
  }
  for (std::size_t i = 0; i < c.materials.size(); ++i) {
    if (c.material_names[i].empty() || find_material(scene, c.material_names[i]) >= 0) {
      throw CommandError("the scene already has a material called '" + c.material_names[i] + "'");
    }
    scene.material_names.push_back(c.material_names[i]);
    scene.materials.push_back(c.materials[i]);
  }
  for (const Object& o : c.objects) scene.objects.push_back(o);
}

void apply_object_command(const DeleteObjects& c, Scene& scene) {
  const std::vector<int> objects = checked_objects(scene, c.objects);
  for (auto it = objects.rbegin(); it != objects.rend(); ++it) {
    scene.objects.erase(scene.objects.begin() + *it);
  }
}

void apply_object_command(const DuplicateObjects& c, Scene& scene) {
  const std::vector<int> objects = checked_objects(scene, c.objects);
  // Beside the originals: their extent along the camera's right, and a tenth of it as a gap.
  const glm::vec3 right = camera_right(scene.camera);
  float lo = std::numeric_limits<float>::infinity(), hi = -lo;
  for (int i : objects) {
    glm::vec3 a, b;
    if (!object_bounds(scene.objects[static_cast<std::size_t>(i)], a, b)) continue;
    for (int k = 0; k < 8; ++k) {
      const glm::vec3 corner((k & 1) ? b.x : a.x, (k & 2) ? b.y : a.y, (k & 4) ? b.z : a.z);
      lo = std::min(lo, glm::dot(corner, right));
      hi = std::max(hi, glm::dot(corner, right));
    }
  }
  const glm::vec3 offset = lo <= hi ? right * (1.1f * (hi - lo)) : glm::vec3(0.0f);
  for (int i : objects) {
    Object copy = scene.objects[static_cast<std::size_t>(i)];
    copy.name = unique_object_name(scene, name_stem(copy.name));
    copy.transform.translate += offset;  // p' moves by offset whatever the pivot
    place_object(copy);
    scene.objects.push_back(std::move(copy));
  }
}

void apply_object_command(const SetHidden& c, Scene& scene) {
  for (int i : checked_objects(scene, c.objects)) {
    scene.objects[static_cast<std::size_t>(i)].hidden = c.hidden;
  }
}

void apply_object_command(const SoloObjects& c, Scene& scene) {
  const std::vector<int> objects = checked_objects(scene, c.objects);
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    scene.objects[i].hidden =
        !std::binary_search(objects.begin(), objects.end(), static_cast<int>(i));
  }
}

void apply_object_command(const RenameObject& c, Scene& scene) {
  checked_objects(scene, {c.object});
  if (c.name.empty()) throw CommandError("an object's name must not be empty");
  const int other = find_object(scene, c.name);
  if (other >= 0 && other != c.object) {
    throw CommandError("object " + std::to_string(other) + " is already called '" + c.name + "'");
  }
  scene.objects[static_cast<std::size_t>(c.object)].name = c.name;
}

void apply_object_command(const TransformObjects& c, Scene& scene) {
  if (c.objects.size() != c.transforms.size()) {
    throw CommandError("one transform per object is needed");
  }
  checked_objects(scene, c.objects);
  for (std::size_t k = 0; k < c.objects.size(); ++k) {
    Object& o = scene.objects[static_cast<std::size_t>(c.objects[k])];
    o.transform = c.transforms[k];
    place_object(o);
  }
}

void apply_object_command(const RenameMaterial& c, Scene& scene) {
  const int material = find_material(scene, c.from);
  if (material < 0) throw CommandError("no material called '" + c.from + "'");
  if (c.to.empty()) throw CommandError("a material's name must not be empty");
  if (c.to != c.from && find_material(scene, c.to) >= 0) {
    throw CommandError("a material is already called '" + c.to + "'");
  }
  scene.material_names[static_cast<std::size_t>(material)] = c.to;
}

void apply_object_command(const AssignMaterial& c, Scene& scene) {
  if (c.material < 0 || c.material >= static_cast<int>(scene.materials.size())) {
    throw CommandError("no material " + std::to_string(c.material));
  }
  for (int i : checked_objects(scene, c.objects)) {
    scene.objects[static_cast<std::size_t>(i)].material = c.material;
  }
}

void apply_object_command(const NewMaterial& c, Scene& scene) {
  const std::vector<int> objects = checked_objects(scene, c.objects);
  scene.material_names.push_back(unique_material_name(scene, c.name));
  scene.materials.push_back(c.material);
  const int material = static_cast<int>(scene.materials.size()) - 1;
  for (int i : objects) scene.objects[static_cast<std::size_t>(i)].material = material;
}

std::string object_command_label(const AddObjects& c) {
  return c.label.empty() ? "add " + std::to_string(c.objects.size()) + " object(s)" : c.label;
}
std::string object_command_label(const DeleteObjects& c) {
  return "delete " + count_text(c.objects.size(), c.objects);
}
std::string object_command_label(const DuplicateObjects& c) {
  return "duplicate " + count_text(c.objects.size(), c.objects);
}
std::string object_command_label(const SetHidden& c) {
  return std::string(c.hidden ? "hide " : "show ") + count_text(c.objects.size(), c.objects);
}
std::string object_command_label(const SoloObjects& c) {
  return "solo " + count_text(c.objects.size(), c.objects);
}
std::string object_command_label(const RenameObject& c) {
  return "rename object " + std::to_string(c.object) + " to '" + c.name + "'";
}
std::string object_command_label(const TransformObjects& c) {
  return "transform " + count_text(c.objects.size(), c.objects);
}
std::string object_command_label(const RenameMaterial& c) {
  return "rename material '" + c.from + "' to '" + c.to + "'";
}
std::string object_command_label(const AssignMaterial& c) {
  return "assign material " + std::to_string(c.material) + " to " +
         count_text(c.objects.size(), c.objects);
}
std::string object_command_label(const NewMaterial& c) {
  return "new material '" + c.name + "' for " + count_text(c.objects.size(), c.objects);
}

std::string transform_merge_key(const TransformObjects& c) {
  std::string key = "transform";
  for (int i : c.objects) key += " " + std::to_string(i);
  return key;
}

}  // namespace gloss
