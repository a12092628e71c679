#include "export/threejs_maps.h"

#include "export/map_export.h"

namespace gloss {

namespace {

using nlohmann::json;

// three.js's constants (src/constants.js).
constexpr int kRepeatWrapping = 1000, kClampToEdgeWrapping = 1001, kMirroredRepeatWrapping = 1002;
constexpr int kUVMapping = 300, kLinearFilter = 1006, kLinearMipmapLinearFilter = 1008;
constexpr int kSRGBEncoding = 3001;  // before r152's colorSpace; later releases ignore it

int wrapping(Wrap wrap) {
  switch (wrap) {
    case Wrap::clamp:
      return kClampToEdgeWrapping;
    case Wrap::mirror:
      return kMirroredRepeatWrapping;
    case Wrap::repeat:
      break;
  }
  return kRepeatWrapping;
}

}  // namespace

std::string ThreejsMaps::texture(std::size_t index, const std::string& name, MapSlot slot) {
  const auto key = std::make_pair(index, static_cast<int>(slot));
  if (const auto found = texture_.find(key); found != texture_.end()) return found->second;
  std::string& uuid = texture_[key];
  const TextureMap& map = scene_.materials[index].map(slot);
  const std::string what = "material '" + name + "': " + to_string(slot) + " map ";
  const MapImage image = map_image(scene_, map, out_);
  if (!image.problem.empty()) {
    notices.push_back(what + "not carried to three.js: " + image.problem);
    return uuid;
  }
  auto [at, added] =
      image_uuid_.try_emplace(image.uri, "gloss-image-" + std::to_string(images.size()));
  if (added) images.push_back({{"uuid", at->second}, {"url", image.uri}});
  const ThreejsTextureTransform t = threejs_texture_transform(map);
  if (!t.exact) {
    notices.push_back(what +
                      "in three.js is approximate: three.js scales after it turns, so a "
                      "scale that differs between u and v turns with the map");
  }
  uuid = "gloss-texture-" + std::to_string(textures.size());
  json out = {{"uuid", uuid},
              {"name", std::string(to_string(slot)) + " " + map.file},
              {"image", at->second},
              {"mapping", kUVMapping},
              {"channel", map.uv_set},
              {"repeat", {t.repeat.x, t.repeat.y}},
              {"offset", {t.offset.x, t.offset.y}},
              {"center", {0.0, 0.0}},
              {"rotation", t.rotation},
              {"wrap", {wrapping(map.wrap[0]), wrapping(map.wrap[1])}},
              {"minFilter", kLinearMipmapLinearFilter},
              {"magFilter", kLinearFilter},
              // three.js's geometries have v up, as gloss's (u, v); the image's top row at v = 1.
              {"flipY", true}};
  if (is_colour_map(slot)) {
    out["colorSpace"] = "srgb";
    out["encoding"] = kSRGBEncoding;
  }
  textures.push_back(out);
  return uuid;
}

json ThreejsMaps::material_fields(std::size_t index, const std::string& name, bool phong) {
  const Material& m = scene_.materials[index];
  json out = json::object();
  const auto note_once = [&](MapSlot slot, const std::string& text) {
    if (phong) notices.push_back("material '" + name + "': " + to_string(slot) + " map " + text);
  };
  for (int s = 0; s < kMapSlots; ++s) {
    const auto slot = static_cast<MapSlot>(s);
    if (!m.map(slot).named()) continue;
    if (slot == MapSlot::shininess) {
      note_once(slot, "not carried to three.js: its materials have no shininess map");
      continue;
    }
    if (slot == MapSlot::specular && !phong) {
      notices.push_back("material '" + name +
                        "': specular map not carried to three.js's "
                        "MeshStandardMaterial (it has no specular map)");
      continue;
    }
    const std::string uuid = texture(index, name, slot);
    if (uuid.empty()) continue;
    switch (slot) {
      case MapSlot::diffuse:
        out["map"] = uuid;
        break;
      case MapSlot::specular:
        out["specularMap"] = uuid;
        note_once(slot, "in three.js is a strength, its red channel, not a colour");
        break;
      case MapSlot::emission:
        out["emissiveMap"] = uuid;
        break;
      case MapSlot::ambient:
        out["aoMap"] = uuid;
        out["aoMapIntensity"] = 1.0;
        note_once(slot, "in three.js is its aoMap: the red channel scales the ambient light");
        break;
      case MapSlot::normal:
        out["normalMap"] = uuid;
        out["normalMapType"] = 0;  // TangentSpaceNormalMap, +Y up as gloss's
        out["normalScale"] = {m.normal_scale, m.normal_scale};
        break;
      case MapSlot::bump:
        out["bumpMap"] = uuid;
        out["bumpScale"] = m.bump_scale;  // height times bumpScale, scene units, as gloss's
        break;
      case MapSlot::opacity: {
        out["alphaMap"] = uuid;
        out["alphaTest"] = 0.5;  // gloss cuts the surface where the map is below 0.5
        const TextureMap& map = m.map(slot);
        if (map.texture != nullptr && map.texture->has_alpha) {
          note_once(slot, "in three.js reads the image's green channel, gloss its alpha");
        }
        break;
      }
      case MapSlot::shininess:
        break;
    }
  }
  return out;
}

}  // namespace gloss
