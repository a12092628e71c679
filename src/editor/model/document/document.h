#pragma once
// The editor's document is a Scene (scene.h); only the command layer writes it. This header holds
// the rules that edits share: the exponent rescaling of the model switch, the document
// comparison, the built-in scene, labels of objects. (Moving a document to a new file:
// io/scene/scene_files.h.)
#include <string>

#include "scene/scene.h"

namespace gloss {

// Keeping a highlight's size across the Phong / Blinn-Phong switch. Near the peak the half vector
// is at half the angle of the reflection vector, so cos(theta/2)^(4a) ~ exp(-a theta^2 / 2) ~
// cos(theta)^a: a Blinn-Phong exponent of 4x the Phong exponent gives the same lobe width in the
// small-angle limit. Results are clamped to the shininess slider's range (scene/fields/fields.cpp).
float blinn_exponent_for_phong(float phong_exponent);
float phong_exponent_for_blinn(float blinn_exponent);
// The exponent that keeps a highlight's size when a material moves from model 'from' to 'to'.
float exponent_for_model(float exponent, ShadingModel from, ShadingModel to);
// The document shown in model: every exponent moved there by exponent_for_model when keep is set
// (the A/B view's two sides, the lobe view's and the pixel inspector's other model).
Scene with_model(const Scene& scene, ShadingModel model, bool keep);

// True when nothing differs (scene/fields/scene_diff.h, the one comparison).
bool same_scene(const Scene& a, const Scene& b);

// Gold and silver spheres under one white light: the scene used when no file is given and the
// shipped default scene is missing. Throws when the preset table cannot be read.
Scene builtin_scene();

// "object 2 (gold sphere)" style names for menus and labels; "object 2" when unnamed.
std::string object_label(const Scene& scene, int object);

}  // namespace gloss
