#include "export/map_export.h"

#include <cmath>
#include <filesystem>

#include "base/text/ascii.h"
#include "io/scene/material_maps.h"

namespace gloss {

namespace {

namespace fs = std::filesystem;

constexpr double kPi = 3.14159265358979323846;

}  // namespace

MapImage map_image(const Scene& scene, const TextureMap& map, const std::string& out_path) {
  MapImage out;
  if (map.file.find('#') != std::string::npos) {
    out.problem = "it is a model's own map (" + map.file + ")";
    return out;
  }
  const std::string base_dir = fs::path(scene.path).parent_path().string();
  out.file = resolve_map_path(map.file, base_dir);
  const std::string ext = lower_extension(out.file);
  if (ext == ".png") {
    out.mime = "image/png";
  } else if (ext == ".jpg" || ext == ".jpeg") {
    out.mime = "image/jpeg";
  } else {
    out.problem = "the image is not PNG or JPEG (" + map.file + ")";
    return out;
  }
  const fs::path out_dir = fs::absolute(fs::path(out_path)).parent_path();
  out.uri = fs::relative(fs::absolute(out.file), out_dir).generic_string();
  if (out.uri.empty()) out.uri = fs::absolute(out.file).generic_string();  // another drive
  return out;
}

GltfTextureTransform gltf_texture_transform(const TextureMap& map) {
  GltfTextureTransform t;
  t.scale = glm::dvec2(map.scale);
  t.rotation = static_cast<double>(map.rotation) * kPi / 180.0;
  const double s = std::sin(t.rotation), c = std::cos(t.rotation);
  t.offset = {map.offset.x - t.scale.y * s, 1.0 - map.offset.y - t.scale.y * c};
  return t;
}

ThreejsTextureTransform threejs_texture_transform(const TextureMap& map) {
  ThreejsTextureTransform t;
  t.repeat = glm::dvec2(map.scale);
  t.offset = glm::dvec2(map.offset);
  t.rotation = map.rotation == 0.0f ? 0.0 : -static_cast<double>(map.rotation) * kPi / 180.0;
  const bool half_turns = std::remainder(static_cast<double>(map.rotation), 180.0) == 0.0;
  t.exact = map.scale.x == map.scale.y || half_turns;
  return t;
}

}  // namespace gloss
