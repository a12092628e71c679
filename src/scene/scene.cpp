#include "scene/scene.h"

#include <algorithm>

namespace gloss {

const char* to_string(ObjectType type) {
  switch (type) {
    case ObjectType::sphere:
      return "sphere";
    case ObjectType::quad:
      return "quad";
    case ObjectType::box:
      return "box";
    case ObjectType::teapot:
      return "teapot";
    case ObjectType::mesh:
      return "mesh";
  }
  return "unknown";
}

Object sphere_object(const std::string& name, const glm::vec3& center, float radius, int material) {
  Object o;
  o.name = name;
  o.type = ObjectType::sphere;
  o.material = material;
  o.center = o.params.center = center;
  o.radius = o.params.radius = radius;
  o.transform.pivot = center;
  return o;
}

int find_material(const Scene& scene, const std::string& name) {
  for (std::size_t i = 0; i < scene.material_names.size(); ++i) {
    if (scene.material_names[i] == name) return static_cast<int>(i);
  }
  return -1;
}

bool has_object_type(const Scene& scene, ObjectType type) {
  return std::any_of(scene.objects.begin(), scene.objects.end(),
                     [type](const Object& o) { return o.type == type; });
}

}  // namespace gloss
