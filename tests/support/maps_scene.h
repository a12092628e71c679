#pragma once
// The scene the map tests put maps on (the raster path's, tests/editor/gl/test_raster_maps.cpp,
// and the ray tracer's, tests/engine/test_engine_maps_reference.cpp, each against the
// reference): two spheres, a floor quad and a box (and the teapot where asked, with its own
// (u, v) and tangents), two lights, materials "a" and "b" without maps, 128 x 96 at one sample
// per pixel, shadows off. And the maps each test's "colours" case puts on a material.
#include <string>

#include "io/scene/scene_loader.h"
#include "support/test_maps.h"

namespace gloss::test {

inline Scene maps_scene(const std::string& path, bool teapot = false) {
  const std::string teapot_object =
      teapot ? R"(, {"type": "teapot", "position": [1.2, -1, 1.4], "scale": [0.35, 0.35, 0.35],
                     "rotate_y": -30, "tessellation": 6, "material": "b"})"
             : "";
  return parse_scene(R"({"camera": {"eye": [0.4, 1.2, 5.5], "target": [0, -0.2, 0], "fov_y": 42},
    "background": [0.1, 0.2, 0.3], "ambient": [0.15, 0.15, 0.15],
    "lights": [{"position": [3, 4, 5], "diffuse": [1, 0.9, 0.8], "specular": [1, 1, 1]},
               {"type": "directional", "direction": [0.3, -1, -0.4], "diffuse": [0.3, 0.3, 0.5],
                "specular": [0.3, 0.3, 0.3]}],
    "materials": {"a": {"ambient": [0.3, 0.2, 0.2], "diffuse": [0.8, 0.6, 0.5],
                        "specular": [0.6, 0.6, 0.6], "emission": [0.05, 0.02, 0], "shininess": 40},
                  "b": {"ambient": [0.2, 0.3, 0.2], "diffuse": [0.7, 0.8, 0.7],
                        "specular": [0.3, 0.3, 0.3], "shininess": 12}},
    "objects": [
      {"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "a"},
      {"type": "sphere", "center": [1.7, -0.4, -0.8], "radius": 0.6, "material": "b"},
      {"type": "quad", "vertices": [[-5, -1, -5], [5, -1, -5], [5, -1, 5], [-5, -1, 5]],
       "material": "b"},
      {"type": "box", "min": [-0.5, -0.5, -0.5], "max": [0.5, 0.5, 0.5], "position": [-1.9, -0.5, 0.6],
       "rotate_y": 25, "material": "a"})" +
                         teapot_object + R"(],
    "render": {"width": 128, "height": 96, "spp": 1, "shadows": false}})",
                     path);
}

// Every colour map: a ramp mirrored and clamped, scaled and moved; a checker as ambient; a
// turned ramp as specular; a fine checker as emission; bumps as shininess.
inline void put_colour_maps(Material& m) {
  m.map(MapSlot::diffuse) = map_of(uv_ramp(32), "ramp");
  m.map(MapSlot::diffuse).wrap = {Wrap::mirror, Wrap::clamp};
  m.map(MapSlot::diffuse).scale = glm::vec2(2.5f, 1.7f);
  m.map(MapSlot::diffuse).offset = glm::vec2(-0.3f, 0.2f);
  m.map(MapSlot::ambient) = map_of(checker(16, 4), "checker");
  m.map(MapSlot::specular) = map_of(uv_ramp(8), "ramp");
  m.map(MapSlot::specular).rotation = 30.0f;
  m.map(MapSlot::emission) = map_of(checker(32, 2), "checker");
  m.map(MapSlot::shininess) = map_of(bumps(32), "bumps");
}

}  // namespace gloss::test
