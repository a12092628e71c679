#pragma once
// How cost grows (`gloss-cli bench --scaling`): the benchmark's 1-spp re-trace and its bare
// Embree baseline on variants of the benchmark scene that change one factor at a time: the
// number of lights, the number of triangles, the image size. Each row runs in a process of its
// own (the CLI spawns one per row), so its peak memory is its own.
#include <string>
#include <vector>

#include "scene/scene.h"

namespace gloss {

// One variant. lights: point lights in a grid under the ceiling (1: the scene's own light).
// teapot_level: 0 keeps the scene's teapot; > 0 puts a 7 x 7 grid of teapots on the floor in
// its place, each tessellated at that level (49 x 32 x 2 x level^2 triangles).
struct ScalingSetup {
  int lights = 1;
  int teapot_level = 0;
  int width = 1280, height = 720;
};

struct ScalingPoint {
  ScalingSetup setup;
  long long triangles = 0;
  double retrace_ms = 0;     // median full 1-spp render (trace, shade, total image)
  double embree_raw_ms = 0;  // median of the same rays through bare Embree
  double ratio = 0;          // median of the paired ratios, as the benchmark's retrace_ratio
  double build_ms = 0;       // scene variant and Embree BVH, once
  double peak_rss_mb = 0;    // of the row's own process (filled in by the CLI)
  std::string skipped;       // why the row was not measured (over the memory budget), or empty
};

// The rows: 1, 4, 16, 64 lights; about 10 k, 1 M and 10 M triangles; 720p, 1440p and 4K.
std::vector<ScalingSetup> scaling_setups();

// The benchmark scene changed as setup says (size in its render block, spp 1).
Scene scaling_scene(const Scene& base, const ScalingSetup& setup);

// Times one row: `runs` alternating pairs of the render and its baseline after a warm-up. A
// variant over the memory budget is not built: its point says so in `skipped`.
ScalingPoint run_scaling_row(const Scene& base, const ScalingSetup& setup, int runs);

// A point as one JSON object (the keys of `bench --json`'s "scaling" rows: lights, triangles,
// width, height, retrace_ms, embree_raw_ms, ratio, build_ms, peak_rss_mb, skipped when
// skipped) and back: the row's process hands its point to the CLI this way.
std::string scaling_point_json_text(const ScalingPoint& point);
ScalingPoint parse_scaling_point(const std::string& text);  // throws InputError

// "L,T,W,H" and back: how the CLI hands a row to the process that measures it.
std::string scaling_setup_text(const ScalingSetup& setup);
ScalingSetup parse_scaling_setup(const std::string& text);  // throws InputError

}  // namespace gloss
