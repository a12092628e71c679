#pragma once
// The editor's document is a Scene (scene.h); only the command layer writes it. This header holds
// the names commands and scripts use for its parts, the comparison that decides whether an edit
// changed anything, and the rules that edits share.
#include <string>

#include "scene/scene.h"

namespace gloss {

// The material constants a command or a script line can set.
enum class MaterialField { ambient, diffuse, specular, emission, shininess };
const char* to_string(MaterialField field);
bool parse_material_field(const std::string& name, MaterialField& field);
glm::vec3& material_colour(Material& material, MaterialField field);  // field != shininess
const glm::vec3& material_colour(const Material& material, MaterialField field);

// The per-light values a command or a script line can set.
enum class LightField { position, ambient, diffuse, specular, attenuation };
const char* to_string(LightField field);
bool parse_light_field(const std::string& name, LightField& field);
glm::vec3& light_value(PointLight& light, LightField field);
const glm::vec3& light_value(const PointLight& light, LightField field);

// The shininess slider's range (the spec allows alpha up to 1e6; the editor offers 0..10000).
constexpr float kMaxShininess = 10000.0f;

// Keeping a highlight's size across the Phong / Blinn-Phong switch. Near the peak the half vector
// is at half the angle of the reflection vector, so cos(theta/2)^(4a) ~ exp(-a theta^2 / 2) ~
// cos(theta)^a: a Blinn-Phong exponent of 4x the Phong exponent gives the same lobe width in the
// small-angle limit. Results are clamped to [0, kMaxShininess].
float blinn_exponent_for_phong(float phong_exponent);
float phong_exponent_for_blinn(float blinn_exponent);
// The exponent that keeps a highlight's size when a material moves from model 'from' to 'to'.
float exponent_for_model(float exponent, ShadingModel from, ShadingModel to);

// True when every value a command can edit is equal (meshes compare by identity: commands never
// modify a mesh in place, they replace objects).
bool same_scene(const Scene& a, const Scene& b);

// Gold and silver spheres under one white light: the scene used when no file is given and the
// shipped default scene is missing. Throws when the preset table cannot be read.
Scene builtin_scene();

// Gives scene a new file path, rewriting the relative file names of its objects (OBJ meshes) so
// they still name the same files from the new folder.
void move_document(Scene& scene, const std::string& path);

// "object 2 (gold sphere)" style names for menus and labels; "object 2" when unnamed.
std::string object_label(const Scene& scene, int object);

}  // namespace gloss
