// The tradeoff's settings and words: the knobs and their names, the image size, the quick
// settings and the notes that go with a table (tradeoff.h). Kept apart from the measuring code.
#include <algorithm>
#include <cmath>

#include "analysis/tradeoff/tradeoff.h"

namespace gloss {

void tradeoff_image_size(const Scene& scene, const TradeoffOptions& options, int& width,
                         int& height) {
  const double aspect = double(scene.render.width) / double(scene.render.height);
  width = options.width > 0 ? options.width : scene.render.width;
  height = options.height > 0 ? options.height : scene.render.height;
  if (options.width > 0 && options.height == 0) {
    height = std::max(1, static_cast<int>(std::lround(options.width / aspect)));
  } else if (options.height > 0 && options.width == 0) {
    width = std::max(1, static_cast<int>(std::lround(options.height * aspect)));
  }
}

TradeoffOptions quick_tradeoff_options() {
  TradeoffOptions o;
  o.width = 256;
  o.runs = 3;
  o.reference_spp = 64;
  o.spp_levels = {1, 2, 4, 8, 16};
  o.adaptive_thresholds = {1.0f / 16, 1.0f / 64};
  o.env_sample_levels = {0, 16, 64, 256};  // 1024 directions: tens of seconds at this size
  return o;
}

std::vector<std::string> tradeoff_notes(const Scene& scene, const TradeoffOptions& options) {
  std::vector<std::string> notes;
  std::size_t meshes = 0, other_meshes = 0;
  for (const Object& o : scene.objects) {
    meshes += o.type != ObjectType::sphere ? 1 : 0;
    other_meshes += o.type != ObjectType::sphere && o.type != ObjectType::teapot ? 1 : 0;
  }
  const int finest = options.tessellation_levels.empty()
                         ? 0
                         : *std::max_element(options.tessellation_levels.begin(),
                                             options.tessellation_levels.end());
  notes.push_back("base of every row: " + std::to_string(options.base_spp) +
                  " spp, full size, exact pow, float, per-pixel, shadows as the scene says" +
                  (has_object_type(scene, ObjectType::teapot)
                       ? ", teapot tessellation " + std::to_string(finest)
                       : "") +
                  "; error against double precision at " + std::to_string(options.reference_spp) +
                  " spp, total image, linear values, every pixel");
  if (!has_object_type(scene, ObjectType::teapot)) {
    notes.push_back("tessellation: skipped, the scene has no teapot" +
                    (other_meshes > 0
                         ? " (its " + std::to_string(other_meshes) +
                               " other mesh object(s) have fixed triangles: quads, boxes and "
                               "OBJ files have no tessellation knob)"
                         : std::string()));
  } else if (other_meshes > 0) {
    notes.push_back("tessellation: applies to the teapot only; the " +
                    std::to_string(other_meshes) + " other mesh object(s) keep their triangles");
  }
  notes.push_back(
      meshes == 0
          ? "shading: no meshes, so gouraud equals per-pixel (spheres stay per pixel)"
          : "shading: gouraud applies to " + std::to_string(meshes) +
                " mesh object(s), spheres stay per pixel; its time comes from the single-ray "
                "reference path in float, not the packet renderer");
  notes.push_back("spp: uniform sampling; adaptive: " + std::to_string(options.adaptive_spp) +
                  " spp in the pixels the refine rule picks at threshold t, the centre elsewhere");
  notes.push_back(
      "resolution: rendered at 1/d of the width and height, upsampled bilinearly "
      "(upsampling included in the time)");
  if (!scene.environment.present()) {
    notes.push_back("env_samples, env_resolution: skipped, the scene has no environment light");
  } else {
    notes.push_back(
        "env_samples: directions per sample towards the environment's exact terms (0: the "
        "prefiltered fast path alone, no visibility, no horizon); env_resolution: the fast "
        "path's texels per lobe width, with env_samples 0; the reference's environment: exact "
        "integrals (shadows off) or 1024-direction estimates (shadows on)");
  }
  bool textured = false;
  for (const Material& m : scene.materials) textured = textured || m.textured();
  notes.push_back(textured ? "maps: map_filter reads every map nearest, bilinear at level 0 or "
                             "trilinear; map_resolution reads each from its pyramid's level k "
                             "(1/2^k of its size), trilinear"
                           : "map_filter, map_resolution: skipped, the scene has no maps");
  if (!scene.render.shadows) {
    notes.push_back(
        "shadows: off in the scene, so the reference has none and 'off' is its "
        "setting");
  }
  return notes;
}

const std::vector<Knob>& tradeoff_knobs() {
  static const std::vector<Knob> knobs{
      Knob::spp,         Knob::adaptive,       Knob::tessellation, Knob::pow,
      Knob::precision,   Knob::shading,        Knob::resolution,   Knob::shadows,
      Knob::env_samples, Knob::env_resolution, Knob::map_filter,   Knob::map_resolution};
  return knobs;
}

const char* to_string(Knob knob) {
  switch (knob) {
    case Knob::spp:
      return "spp";
    case Knob::adaptive:
      return "adaptive";
    case Knob::tessellation:
      return "tessellation";
    case Knob::pow:
      return "pow";
    case Knob::precision:
      return "precision";
    case Knob::shading:
      return "shading";
    case Knob::resolution:
      return "resolution";
    case Knob::shadows:
      return "shadows";
    case Knob::env_samples:
      return "env_samples";
    case Knob::env_resolution:
      return "env_resolution";
    case Knob::map_filter:
      return "map_filter";
    case Knob::map_resolution:
      return "map_resolution";
  }
  return "?";
}

bool parse_knob(const std::string& name, Knob& knob) {
  for (const Knob k : tradeoff_knobs()) {
    if (name == to_string(k)) {
      knob = k;
      return true;
    }
  }
  return false;
}

}  // namespace gloss
