#pragma once
// The maps' part of `gloss-cli bench` (docs/engine.md, "Maps"): the benchmark scene with a
// 2048 x 2048 map on every surface's diffuse colour and a normal map on every quad's (the
// floor and the walls), against the same scene untextured, in alternating pairs: the 1-spp
// re-trace, and a kd edit on the textured material against today's re-shade, with the streaming
// floor of the bytes the textured re-shade reads and writes.
#include "analysis/bench/bench.h"
#include "scene/scene.h"

namespace gloss {

// The scene with the benchmark's maps: made in memory (no files), side x side texels.
Scene with_benchmark_maps(const Scene& scene, int side = 2048);

// Fills report's textured_* figures.
void measure_textured(const Scene& scene, const BenchOptions& options, BenchReport& report);

}  // namespace gloss
