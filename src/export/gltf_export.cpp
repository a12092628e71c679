#include "export/gltf_export.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <utility>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <nlohmann/json.hpp>

#include "base/text/ascii.h"
#include "base/atomic_file.h"
#include "base/error.h"
#include "base/version.h"
#include "export/gltf_buffer.h"
#include "export/map_export.h"
#include "scene/geometry/tangent_space.h"

namespace gloss {

namespace {

using nlohmann::json;
namespace fs = std::filesystem;

constexpr double kPi = 3.14159265358979323846;

json vec(const glm::vec3& v) {
  return json::array({v.x, v.y, v.z});
}

// The rotation (x, y, z, w) of a node whose -Z points along forward and +Y as close to up as
// forward allows (glTF's cameras and lights look down their -Z).
json rotation_towards(glm::dvec3 forward, glm::dvec3 up) {
  forward = glm::normalize(forward);
  if (std::abs(glm::dot(forward, glm::normalize(up))) > 0.999) up = {1.0, 0.0, 0.0};
  if (std::abs(glm::dot(forward, up)) > 0.999) up = {0.0, 0.0, 1.0};
  const glm::dvec3 right = glm::normalize(glm::cross(forward, up));
  const glm::dvec3 true_up = glm::cross(right, forward);
  const glm::dquat q = glm::quat_cast(glm::dmat3(right, true_up, -forward));
  return json::array({q.x, q.y, q.z, q.w});
}

// gloss's wrap as glTF's sampler mode.
int wrap_mode(Wrap wrap) {
  switch (wrap) {
    case Wrap::clamp:
      return 33071;
    case Wrap::mirror:
      return 33648;
    case Wrap::repeat:
      break;
  }
  return 10497;
}

// A mesh for a normal-mapped material: glTF viewers make a primitive's missing tangents each in
// their own way (the validator warns), so a flat mesh gets its face normals (corners unwelded)
// and the mesh MikkTSpace tangents (scene/geometry/tangent_space.h), the ones gloss shades with.
Mesh with_tangent_space(const Mesh& in) {
  if (in.smooth() && in.tangents.size() == in.positions.size()) return in;
  Mesh out = in;
  if (!in.smooth()) {
    out = Mesh{};
    for (const glm::uvec3& t : in.triangles) {
      const glm::vec3 e1 = in.positions[t[1]] - in.positions[t[0]];
      const glm::vec3 e2 = in.positions[t[2]] - in.positions[t[0]];
      const glm::vec3 n = glm::normalize(glm::cross(e1, e2));
      const auto base = static_cast<unsigned>(out.positions.size());
      for (int k = 0; k < 3; ++k) {
        out.positions.push_back(in.positions[t[k]]);
        out.normals.push_back(n);
        for (int set = 0; set < 2; ++set) {
          if (in.uv[set].size() == in.positions.size()) out.uv[set].push_back(in.uv[set][t[k]]);
        }
      }
      out.triangles.emplace_back(base, base + 1, base + 2);
    }
  }
  generate_tangents(out);
  return out;
}

struct Writer {
  Writer(const Scene& s, const std::vector<MaterialConversion>& c, std::string p)
      : scene(s), conversions(c), path(std::move(p)) {}
  const Scene& scene;
  const std::vector<MaterialConversion>& conversions;
  std::string path;
  bool binary = false;
  GltfBuffer buffer;
  json doc;
  GltfExportResult result;

  // The texture for a map; -1 (with a notice) when it cannot be carried.
  int texture(const TextureMap& map, const std::string& material, MapSlot slot) {
    const MapImage image_file = map_image(scene, map, path);
    if (!image_file.problem.empty()) {
      result.notices.push_back("material '" + material + "': " + to_string(slot) +
                               " map not carried: " + image_file.problem);
      return -1;
    }
    json image;
    if (binary) {
      const std::string bytes = read_text_file(image_file.file);
      image = {{"bufferView", buffer.add_view(bytes.data(), bytes.size(), 0)},
               {"mimeType", image_file.mime}};
    } else {
      image = {{"uri", image_file.uri}};
    }
    doc["images"].push_back(image);
    doc["samplers"].push_back({{"wrapS", wrap_mode(map.wrap[0])},
                               {"wrapT", wrap_mode(map.wrap[1])},
                               {"magFilter", 9729},
                               {"minFilter", 9987}});
    doc["textures"].push_back(
        {{"source", doc["images"].size() - 1}, {"sampler", doc["samplers"].size() - 1}});
    return static_cast<int>(doc["textures"].size()) - 1;
  }

  // A textureInfo for map's texture t, with KHR_texture_transform when the map is scaled,
  // turned or moved.
  json texture_info(const TextureMap& map, int t) {
    json info = {{"index", t}, {"texCoord", map.uv_set}};
    if (map.scale == glm::vec2(1.0f) && map.rotation == 0.0f && map.offset == glm::vec2(0.0f)) {
      return info;
    }
    const GltfTextureTransform transform = gltf_texture_transform(map);
    info["extensions"]["KHR_texture_transform"] = {
        {"offset", {transform.offset.x, transform.offset.y}},
        {"rotation", transform.rotation},
        {"scale", {transform.scale.x, transform.scale.y}},
        {"texCoord", map.uv_set}};
    used_extension("KHR_texture_transform");
    return info;
  }

  json material(std::size_t index) {
    const Material& m = scene.materials[index];
    const MaterialConversion& c = conversions.at(index);
    const MetalRough& g = c.gltf.material;
    json pbr = {{"baseColorFactor", {g.base_colour.x, g.base_colour.y, g.base_colour.z, 1.0}},
                {"metallicFactor", g.metallic},
                {"roughnessFactor", g.roughness}};
    json out = {{"name", c.name}, {"pbrMetallicRoughness", pbr}, {"doubleSided", true}};
    // glTF's emissive factor is at most 1; a brighter ke keeps its colour there and its
    // strength in KHR_materials_emissive_strength.
    const float peak = std::max({m.emission.x, m.emission.y, m.emission.z});
    if (peak > 0.0f) {
      const float strength = std::max(peak, 1.0f);
      out["emissiveFactor"] = vec(m.emission / strength);
      if (strength > 1.0f) {
        out["extensions"]["KHR_materials_emissive_strength"] = {{"emissiveStrength", strength}};
        used_extension("KHR_materials_emissive_strength");
      }
    }
    json maps = json::object();
    for (int s = 0; s < kMapSlots; ++s) {
      const auto slot = static_cast<MapSlot>(s);
      const TextureMap& map = m.map(slot);
      if (!map.named()) continue;
      maps[to_string(slot)] = map.file;
      const char* key = slot == MapSlot::diffuse    ? "baseColorTexture"
                        : slot == MapSlot::normal   ? "normalTexture"
                        : slot == MapSlot::emission ? "emissiveTexture"
                                                    : nullptr;
      if (key == nullptr) {
        result.notices.push_back("material '" + c.name + "': " + to_string(slot) +
                                 " map not carried: glTF has no slot for it (kept in extras)");
        continue;
      }
      const int t = texture(map, c.name, slot);
      if (t < 0) continue;
      json info = texture_info(map, t);
      if (slot == MapSlot::normal) info["scale"] = m.normal_scale;
      if (slot == MapSlot::diffuse) {
        out["pbrMetallicRoughness"][key] = info;
      } else {
        out[key] = info;
      }
    }
    const auto residual = [](const LobeResidual& r) {
      return json{{"l2", r.l2}, {"l2_relative", r.l2_relative}, {"lightness", r.lightness}};
    };
    out["extras"]["gloss"] = {{"ambient", vec(m.ambient)},
                              {"diffuse", vec(m.diffuse)},
                              {"specular", vec(m.specular)},
                              {"emission", vec(m.emission)},
                              {"shininess", m.shininess},
                              {"normal_scale", m.normal_scale},
                              {"bump_scale", m.bump_scale},
                              {"model", to_string(scene.render.model)},
                              {"energy_normalize", scene.render.energy_normalize},
                              {"fit_residual", residual(c.gltf.residual)},
                              {"maps", maps}};
    if (!m.preset.empty()) out["extras"]["gloss"]["preset"] = m.preset;
    return out;
  }

  void used_extension(const char* name) {
    json& used = doc["extensionsUsed"];
    if (std::find(used.begin(), used.end(), name) == used.end()) used.push_back(name);
  }

  // KHR_lights_punctual's light for a gloss light, and the node that places it. Photometric
  // units as glTF viewers use them (a Lambertian base b under a point light of I candela at
  // distance d sends b I n.l / (pi d^2)): the intensity that sends what gloss sends at the
  // distance from the light to the camera's target (gloss's attenuation is 1 / (c0 + c1 d +
  // c2 d^2), glTF's always 1 / d^2; the exact light is in extras).
  void light(std::size_t index, json& nodes, json& camera_children) {
    const Light& l = scene.lights[index];
    const float peak = std::max({l.diffuse.x, l.diffuse.y, l.diffuse.z});
    json out = {{"name", "light" + std::to_string(index)},
                {"color", peak > 0.0f ? vec(l.diffuse / peak) : json::array({1.0, 1.0, 1.0})}};
    double intensity = kPi * peak;  // directional: lux
    if (has_position(l.type)) {
      const double d = glm::length(glm::dvec3(scene.camera.target) - glm::dvec3(l.position));
      const glm::dvec3 c(l.attenuation);
      const double att = c.x + c.y * d + c.z * d * d;
      intensity = att > 0.0 ? kPi * peak * d * d / att : 0.0;
    }
    out["intensity"] = intensity;
    out["type"] = to_string(l.type);
    if (l.type == LightType::spot) {
      const double outer = std::clamp(static_cast<double>(l.cutoff), 1e-3, 90.0) * kPi / 180.0;
      double inner = std::min(l.inner, l.cutoff) * kPi / 180.0;
      if (inner >= outer) inner = outer * 0.999;  // gloss's hard edge; glTF needs inner < outer
      out["spot"] = {{"innerConeAngle", inner}, {"outerConeAngle", outer}};
    }
    out["extras"]["gloss"] = {{"type", to_string(l.type)},
                              {"position", vec(l.position)},
                              {"direction", vec(l.direction)},
                              {"ambient", vec(l.ambient)},
                              {"diffuse", vec(l.diffuse)},
                              {"specular", vec(l.specular)},
                              {"attenuation", vec(l.attenuation)},
                              {"cutoff", l.cutoff},
                              {"inner", l.inner},
                              {"exponent", l.exponent},
                              {"follow_camera", l.follow_camera}};
    doc["extensions"]["KHR_lights_punctual"]["lights"].push_back(out);
    json node = {{"name", "light" + std::to_string(index)},
                 {"extensions", {{"KHR_lights_punctual", {{"light", index}}}}}};
    if (has_position(l.type)) node["translation"] = vec(l.position);
    if (l.type != LightType::point) {
      node["rotation"] = rotation_towards(glm::dvec3(l.direction), {0.0, 1.0, 0.0});
    }
    nodes.push_back(node);
    // A headlight's direction is in camera space: its node is the camera's child.
    if (l.type == LightType::directional && l.follow_camera) {
      camera_children.push_back(nodes.size() - 1);
    } else {
      doc["scenes"][0]["nodes"].push_back(nodes.size() - 1);
    }
  }

  void build(const GltfExportOptions& options) {
    doc["asset"] = {{"version", "2.0"}, {"generator", std::string("gloss ") + gloss_version()}};
    doc["scene"] = 0;
    doc["scenes"] = json::array({{{"name", "gloss"}, {"nodes", json::array()}}});
    json nodes = json::array(), meshes = json::array(), materials = json::array();
    for (std::size_t i = 0; i < scene.materials.size(); ++i) materials.push_back(material(i));

    Mesh sphere;
    for (const Object& o : scene.objects) {
      json node = {{"name", o.name}, {"mesh", meshes.size()}};
      if (o.type == ObjectType::sphere) {
        if (sphere.positions.empty()) sphere = unit_sphere(options.sphere_segments);
        node["translation"] = vec(o.center);
        node["scale"] = {o.radius, o.radius, o.radius};
        meshes.push_back(
            {{"name", o.name}, {"primitives", {mesh_primitive(buffer, sphere, o.material)}}});
      } else if (o.mesh != nullptr && !o.mesh->triangles.empty()) {
        const bool normal_mapped = o.material >= 0 &&
                                   o.material < static_cast<int>(scene.materials.size()) &&
                                   scene.materials[o.material].map(MapSlot::normal).named();
        Mesh tangent_mesh;
        if (normal_mapped) tangent_mesh = with_tangent_space(*o.mesh);
        const Mesh& mesh = normal_mapped ? tangent_mesh : *o.mesh;
        meshes.push_back(
            {{"name", o.name}, {"primitives", {mesh_primitive(buffer, mesh, o.material)}}});
      } else {
        continue;
      }
      nodes.push_back(node);
      doc["scenes"][0]["nodes"].push_back(nodes.size() - 1);
    }

    // The camera: aspect from the render size; glTF's camera looks down its -Z, +Y up.
    const Camera& cam = scene.camera;
    doc["cameras"] = json::array({{{"name", "camera"},
                                   {"type", "perspective"},
                                   {"perspective",
                                    {{"yfov", cam.fov_y * kPi / 180.0},
                                     {"aspectRatio", static_cast<double>(scene.render.width) /
                                                         std::max(1, scene.render.height)},
                                     {"znear", 0.01}}}}});
    nodes.push_back({{"name", "camera"},
                     {"camera", 0},
                     {"translation", vec(cam.eye)},
                     {"rotation", rotation_towards(glm::dvec3(cam.target) - glm::dvec3(cam.eye),
                                                   glm::dvec3(cam.up))}});
    const std::size_t camera_node = nodes.size() - 1;
    doc["scenes"][0]["nodes"].push_back(camera_node);
    json camera_children = json::array();
    for (std::size_t i = 0; i < scene.lights.size(); ++i) light(i, nodes, camera_children);
    if (!scene.lights.empty()) used_extension("KHR_lights_punctual");
    if (!camera_children.empty()) nodes[camera_node]["children"] = camera_children;
    if (scene.environment.present()) {
      result.notices.push_back("the environment light is not carried: glTF has no environment");
    }

    doc["nodes"] = nodes;
    if (!meshes.empty()) doc["meshes"] = meshes;
    if (!materials.empty()) doc["materials"] = materials;
    doc["scenes"][0]["extras"]["gloss"] = {{"ambient", vec(scene.ambient)},
                                           {"background", vec(scene.background)},
                                           {"model", to_string(scene.render.model)},
                                           {"energy_normalize", scene.render.energy_normalize}};
    for (const char* key : {"images", "samplers", "textures"}) {
      if (doc.contains(key) && doc[key].is_null()) doc.erase(key);
    }
    if (!buffer.bytes().empty()) {
      doc["bufferViews"] = buffer.views();
      doc["accessors"] = buffer.accessors();
      json b = {{"byteLength", buffer.bytes().size()}};
      if (!binary) b["uri"] = fs::path(bin_path()).filename().string();
      doc["buffers"] = json::array({b});
    }
  }

  std::string bin_path() const { return (fs::path(path).replace_extension(".bin")).string(); }

  void write() {
    std::string text = doc.dump(binary ? -1 : 1);
    if (!binary) {
      result.bytes = text.size() + 1 + buffer.bytes().size();
      if (buffer.bytes().empty()) {
        write_text_atomically(path, text + "\n");
        return;
      }
      // The pair changes together: the .bin is written to its temporary, the .gltf is put in
      // place, and only then the .bin is. A failure before that leaves both old files; only a
      // failed rename within the folder, after the .gltf, could leave them mismatched.
      write_atomically(bin_path(), [&](const std::string& temp) {
        std::FILE* file = std::fopen(temp.c_str(), "wb");
        if (file == nullptr) throw_write_error(bin_path(), errno);
        const bool written = std::fwrite(buffer.bytes().data(), 1, buffer.bytes().size(), file) ==
                             buffer.bytes().size();
        const int error = errno;
        if (std::fclose(file) != 0 || !written)
          throw_write_error(bin_path(), written ? errno : error);
        write_text_atomically(path, text + "\n");
      });
      return;
    }
    // GLB: a 12-byte header, the JSON chunk padded with spaces, the BIN chunk with zeros.
    while (text.size() % 4 != 0) text.push_back(' ');
    std::string bin = buffer.bytes();
    while (bin.size() % 4 != 0) bin.push_back('\0');
    std::string out;
    const auto u32 = [&out](std::uint32_t x) {
      char b[4];
      std::memcpy(b, &x, 4);  // glTF is little-endian, as x86-64
      out.append(b, 4);
    };
    // GLB's lengths are 32-bit: a larger file has no valid header (the .gltf form has no limit).
    const std::uint64_t length =
        12 + 8 + std::uint64_t(text.size()) + (bin.empty() ? 0 : 8 + std::uint64_t(bin.size()));
    if (length > 0xffffffffu) {
      throw RuntimeFailure("cannot write " + path +
                           ": a GLB holds at most 4 GiB and this one needs " +
                           std::to_string(length >> 20) + " MiB; export to .gltf instead");
    }
    const auto total = static_cast<std::uint32_t>(length);
    u32(0x46546C67u);  // "glTF"
    u32(2);
    u32(total);
    u32(static_cast<std::uint32_t>(text.size()));
    u32(0x4E4F534Au);  // "JSON"
    out += text;
    if (!bin.empty()) {
      u32(static_cast<std::uint32_t>(bin.size()));
      u32(0x004E4942u);  // "BIN\0"
      out += bin;
    }
    write_text_atomically(path, out);
    result.bytes = out.size();
  }
};

}  // namespace

bool is_gltf_path(const std::string& path) {
  const std::string ext = lower_extension(path);
  return ext == ".gltf" || ext == ".glb";
}

GltfExportResult export_gltf(const Scene& scene, const std::vector<MaterialConversion>& conversions,
                             const std::string& path, const GltfExportOptions& options) {
  if (!is_gltf_path(path)) {
    throw InputError(path, "a glTF export is written to FILE.gltf or FILE.glb");
  }
  Writer w(scene, conversions, path);
  w.binary = lower_extension(path) == ".glb";
  w.build(options);
  w.write();
  return w.result;
}

}  // namespace gloss
