#pragma once
// The benchmark scene as `gloss-cli bench` sizes it (cornell-teapot, 1280 x 720, one sample per
// pixel), optionally with the bench's 2048 x 2048 maps (analysis/bench/texture_bench.h), for the
// micro-benchmarks that profile one of its figures.
#include "analysis/bench/texture_bench.h"
#include "base/assets.h"
#include "io/scene/scene_loader.h"

namespace gloss {

inline Scene benchmark_scene_720p(bool maps = false) {
  Scene scene = load_scene(asset_path("scenes/cornell-teapot.json"));
  scene.render.width = 1280;
  scene.render.height = 720;
  scene.render.spp = 1;
  return maps ? with_benchmark_maps(scene) : scene;
}

}  // namespace gloss
