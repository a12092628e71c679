#include "scene/fields/scene_diff.h"

#include "scene/fields/fields.h"

namespace gloss {

namespace {

// Raises diff by the class of every field of table whose values differ.
template <class S>
void diff_fields(const FieldTable<S>& table, const S& a, const S& b, SceneDiff& diff) {
  for (const Field<S>& f : table) {
    if (f.get(a) != f.get(b)) {
      diff.change = raise(diff.change, f.change);
      diff.any = true;
    }
  }
}

bool same_shape(const Object& a, const Object& b) {
  if (a.type != b.type || a.mesh != b.mesh) return false;
  return a.type != ObjectType::sphere || (a.center == b.center && a.radius == b.radius);
}

bool same_params(const ShapeParams& a, const ShapeParams& b) {
  for (int i = 0; i < 4; ++i) {
    if (a.quad[i] != b.quad[i]) return false;
  }
  return a.center == b.center && a.radius == b.radius && a.box_min == b.box_min &&
         a.box_max == b.box_max && a.file == b.file && a.group == b.group &&
         a.position == b.position && a.scale == b.scale && a.rotate_y == b.rotate_y &&
         a.tessellation == b.tessellation && a.smooth == b.smooth &&
         a.crease_angle == b.crease_angle;
}

}  // namespace

const char* to_string(ChangeClass change) {
  switch (change) {
    case ChangeClass::none:
      return "none";
    case ChangeClass::shade:
      return "shade";
    case ChangeClass::exponent:
      return "exponent";
    case ChangeClass::texture:
      return "texture";
    case ChangeClass::environment:
      return "environment";
    case ChangeClass::light:
      return "light";
    case ChangeClass::full:
      return "full";
  }
  return "?";
}

SceneDiff diff_scenes(const Scene& before, const Scene& after) {
  SceneDiff diff;
  diff_fields(camera_fields(), before.camera, after.camera, diff);
  diff_fields(render_fields(), before.render, after.render, diff);
  diff_fields(scene_fields(), before, after, diff);
  diff_fields(environment_fields(), before.environment, after.environment, diff);
  // Another map (or none): its factors anew; added or removed, the plan changes too
  // (engine/change_class.h raises that to `light`).
  if (before.environment.map != after.environment.map) {
    diff.change = raise(diff.change, ChangeClass::environment);
    diff.any = true;
  }
  diff.any = diff.any || before.environment.file != after.environment.file;
  // Lights added or removed need new shadow rays and factors.
  if (before.lights.size() != after.lights.size()) {
    diff.change = raise(diff.change, ChangeClass::light);
    diff.any = true;
  } else {
    for (std::size_t i = 0; i < before.lights.size(); ++i) {
      diff_fields(light_fields(), before.lights[i], after.lights[i], diff);
    }
  }
  if (before.materials.size() != after.materials.size()) {
    diff.change = raise(diff.change, ChangeClass::exponent);
    diff.any = true;
    for (const Scene* s : {&before, &after}) {
      for (const Material& m : s->materials) {
        if (m.has_map(MapSlot::opacity)) diff.geometry = true;
      }
    }
    if (diff.geometry) diff.change = ChangeClass::full;
  } else {
    for (std::size_t m = 0; m < before.materials.size(); ++m) {
      diff_fields(material_fields(), before.materials[m], after.materials[m], diff);
      // The reference changes no Phong pixel (ChangeClass::none) but is part of the document.
      diff.any = diff.any || before.materials[m].preset != after.materials[m].preset ||
                 before.materials[m].reference != after.materials[m].reference;
      // An opacity map cuts the geometry: what rays hit changes (engine/trace/cut_outs.h).
      if (before.materials[m].map(MapSlot::opacity) != after.materials[m].map(MapSlot::opacity)) {
        diff.change = ChangeClass::full;
        diff.geometry = true;
      }
    }
  }
  auto cut = [](const Scene& s, int material) {
    return material >= 0 && material < static_cast<int>(s.materials.size()) &&
           s.materials[static_cast<std::size_t>(material)].has_map(MapSlot::opacity);
  };
  if (before.objects.size() != after.objects.size()) {
    diff.change = ChangeClass::full;
    diff.geometry = diff.any = true;
  } else {
    for (std::size_t i = 0; i < before.objects.size(); ++i) {
      const Object& a = before.objects[i];
      const Object& b = after.objects[i];
      if (!same_shape(a, b) || a.hidden != b.hidden) {
        diff.change = ChangeClass::full;
        diff.geometry = diff.any = true;
      }
      // Transforms and hidden flags by their tables (geometry changes: the placed shape above
      // differs too, but a pivot moved under an identity transform changes only the file).
      diff_fields(transform_fields(), a.transform, b.transform, diff);
      diff_fields(object_fields(), a, b, diff);
      if (a.material != b.material) {
        diff.change = raise(diff.change, ChangeClass::exponent);
        diff.any = true;
        if (cut(before, a.material) || cut(after, b.material)) {  // cut out now, or no more
          diff.change = ChangeClass::full;
          diff.geometry = true;
        }
      }
      diff.any = diff.any || a.name != b.name || !same_params(a.params, b.params) ||
                 a.shape != b.shape || a.transform.pivot_set != b.transform.pivot_set;
    }
  }
  diff.any = diff.any || before.material_names != after.material_names || before.path != after.path;
  return diff;
}

}  // namespace gloss
