// Micro-benchmarks of the maps' cost in the first pass (docs/engine.md, "Maps"): the benchmark
// scene at 1280x720, 1 spp, untextured and with the bench's 2048^2 maps (a colour map on every
// surface, a normal map on the quads), for profiling the textured re-trace on its own.
#include <benchmark/benchmark.h>

#include <memory>

#include "benchmark_scene.h"
#include "engine/render_context.h"
#include "engine/shade/pixel_factors.h"
#include "engine/trace/embree_scene.h"
#include "engine/trace/sample_cache.h"
#include "engine/trace/single_sample_pass.h"

namespace gloss {
namespace {

// range(0): 1 = with the maps.
void BM_FirstPass720p(benchmark::State& state) {
  const Scene scene = benchmark_scene_720p(state.range(0) != 0);
  const EmbreeScene embree(scene);
  const RenderContext ctx = make_render_context(scene, embree);
  SampleCache cache = make_sample_cache(scene, 1280, 720, 1);
  PixelFactors factors;
  Image total;
  for (auto _ : state) {
    reset_sample_cache(cache, scene, 1280, 720, 1);
    trace_single_sample(cache, ctx, factors, &total);
    benchmark::DoNotOptimize(total.pixels.data());
  }
  state.SetItemsProcessed(state.iterations() * 1280 * 720);
}
BENCHMARK(BM_FirstPass720p)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

// A kd edit: recombination from the 1-spp cache (range(0): 1 = with the maps).
void BM_KdEdit720p(benchmark::State& state) {
  const Scene scene = benchmark_scene_720p(state.range(0) != 0);
  const EmbreeScene embree(scene);
  SampleCache cache = make_sample_cache(scene, 1280, 720, 1);
  PixelFactors factors;
  trace_single_sample(cache, make_render_context(scene, embree), factors);
  Scene edited = scene;
  for (Material& m : edited.materials) m.diffuse *= 0.9f;
  const RenderContext ctx = make_render_context(edited, embree);
  TermImages out;
  for (auto _ : state) {
    combine_terms(factors, ctx, out, false);
    benchmark::DoNotOptimize(out.total.pixels.data());
  }
  state.SetItemsProcessed(state.iterations() * 1280 * 720);
}
BENCHMARK(BM_KdEdit720p)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond)->UseRealTime();

}  // namespace
}  // namespace gloss
