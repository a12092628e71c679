#pragma once
// Short forms of the editor's SetField command (editor/model/document/command.h) for tests.
#include <string>

#include "editor/model/document/command.h"

namespace gloss::test {

inline Command set_material(int object, const std::string& key, const glm::vec3& colour) {
  return SetField{FieldPart::material, object, key, vec3_value(colour)};
}
inline Command set_shininess(int object, double alpha) {
  return SetField{FieldPart::material, object, "shininess", number_value(alpha)};
}
inline Command set_light(int light, const std::string& key, const glm::vec3& value) {
  return SetField{FieldPart::light, light, key, vec3_value(value)};
}
inline Command set_render(const std::string& key, double value) {
  return SetField{FieldPart::render, 0, key, number_value(value)};
}
inline Command set_scene(const std::string& key, const glm::vec3& colour) {
  return SetField{FieldPart::scene, 0, key, vec3_value(colour)};
}

}  // namespace gloss::test
