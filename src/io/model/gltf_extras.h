#pragma once
// The exact Phong constants gloss writes into a glTF material's extras.gloss
// (export/gltf_export.h), read back so that gloss -> glTF -> gloss loses nothing. Private to io.
// assimp does not hand material extras over, so the file's JSON (a .gltf, or a .glb's JSON chunk)
// is read here with nlohmann-json; JSON it cannot parse gives no extras (assimp's reader reports
// real errors), a .glb whose JSON chunk does not fit the file is an InputError naming it.
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace gloss {

struct GlossExtras {
  std::string name;  // the glTF material's name
  glm::vec3 ambient{0.0f}, diffuse{0.0f}, specular{0.0f}, emission{0.0f};
  float shininess = 0.0f;
};

struct GltfMaterialExtras {
  bool parsed = false;  // the file's JSON was read (then materials has one entry per material)
  // Per glTF material, in the file's order: its extras.gloss, or nothing. Extras with a
  // missing, negative or non-finite constant count as absent.
  std::vector<std::optional<GlossExtras>> materials;
};

// Throws InputError naming the file for a .glb cut short or whose JSON chunk does not fit it.
GltfMaterialExtras read_gloss_extras(const std::string& path);

// The extras of the one material called name; null when none or several have that name.
const GlossExtras* find_gloss_extras(const GltfMaterialExtras& extras, const std::string& name);

}  // namespace gloss
