#pragma once
// The editable fields of the document, one table per struct (scene/fields/field.h): every consumer
// (scene reader and writer, validation, scene comparison, editor commands, scripts, panels)
// iterates over these. Table order is the order files list the keys and panels show them.
#include "scene/camera.h"
#include "scene/fields/field.h"
#include "scene/light.h"
#include "scene/material.h"
#include "scene/physical_reference.h"
#include "scene/render_settings.h"
#include "scene/scene.h"

namespace gloss {

const FieldTable<Material>& material_fields();
// A material's physical reference (its optional `reference` block).
const FieldTable<PhysicalReference>& reference_fields();
const FieldTable<Light>& light_fields();
const FieldTable<RenderSettings>& render_fields();
const FieldTable<Camera>& camera_fields();
// The environment light's numbers (its map is read and compared apart: scene_diff.h).
const FieldTable<Environment>& environment_fields();
// The scene's own fields (background, A_scene).
const FieldTable<Scene>& scene_fields();
// An object's transform (the "transform" block of an object) and its own fields ("hidden").
const FieldTable<ObjectTransform>& transform_fields();
const FieldTable<Object>& object_fields();

// Whether a and b hold equal values in every field of table.
template <class S>
bool same_fields(const FieldTable<S>& table, const S& a, const S& b) {
  for (const Field<S>& f : table) {
    if (f.get(a) != f.get(b)) return false;
  }
  return true;
}

}  // namespace gloss
