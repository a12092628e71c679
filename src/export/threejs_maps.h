#pragma once
// A scene's maps as three.js textures (docs/export.md, "three.js"): the `images` and `textures`
// of three.js's JSON Object format (ObjectLoader), and the fields that hook them to a material
// (`map`, `specularMap`, `emissiveMap`, `normalMap` + `normalScale`, `bumpMap` + `bumpScale`,
// `alphaMap` + `alphaTest`, `aoMap`). Private to export.
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/scene.h"

namespace gloss {

class ThreejsMaps {
 public:
  // out_path: the JSON file, which the images' URLs are relative to.
  ThreejsMaps(const Scene& scene, std::string out_path)
      : scene_(scene), out_(std::move(out_path)) {}

  // The map fields of scene.materials[index] (called `name`) on three.js's MeshPhongMaterial
  // (phong) or MeshStandardMaterial; a map three.js cannot take, or takes otherwise than gloss
  // reads it, is a notice (once per material and map).
  nlohmann::json material_fields(std::size_t index, const std::string& name, bool phong);

  nlohmann::json images = nlohmann::json::array();
  nlohmann::json textures = nlohmann::json::array();
  std::vector<std::string> notices;

 private:
  // The texture's uuid for a material's map; "" when it cannot be carried (noted).
  std::string texture(std::size_t index, const std::string& name, MapSlot slot);

  const Scene& scene_;
  std::string out_;
  std::map<std::string, std::string> image_uuid_;               // URL -> uuid
  std::map<std::pair<std::size_t, int>, std::string> texture_;  // (material, slot) -> uuid
};

}  // namespace gloss
