// The physical reference's costs (built by default, not tests):
//   ./build/benchmarks/gloss_benchmarks --benchmark_filter='Fit|Preview'
// - a fit of Phong or Blinn-Phong to a reference, which the editor runs on a button press
//   (issue 23: under a second on the 2-core development machine);
// - the editor's "material | reference" B side (render_reference<double> with the physical
//   option at 1 spp) against the ray tracer's 1-spp frame of the same scene and size, both in
//   this run, so their ratio is measured under the same load.
#include <benchmark/benchmark.h>

#include "base/assets.h"
#include "engine/renderer.h"
#include "io/scene/scene_loader.h"
#include "physical/phong_fit.h"
#include "reference/reference_renderer.h"

namespace gloss {
namespace {

// range(0): roughness in hundredths; range(1): 0 Phong, 1 Blinn-Phong; range(2): 0 l2,
// 1 lightness.
void BM_FitToGold(benchmark::State& state) {
  PhysicalReference gold;
  gold.roughness = static_cast<float>(state.range(0)) / 100.0f;
  FitOptions options;
  options.model = state.range(1) != 0 ? ShadingModel::blinn_phong : ShadingModel::phong;
  options.metric = state.range(2) != 0 ? LobeMetric::lightness : LobeMetric::l2;
  for (auto _ : state) benchmark::DoNotOptimize(fit_phong_to_reference(gold, options));
}
BENCHMARK(BM_FitToGold)
    ->Args({5, 0, 0})
    ->Args({20, 0, 0})
    ->Args({20, 1, 0})
    ->Args({20, 0, 1})
    ->Args({20, 1, 1})
    ->Args({60, 0, 0})
    ->Unit(benchmark::kMillisecond);

// The shipped spheres scene with measured gold and silver references, at the preview size
// range(0) x range(1), 1 sample per pixel.
Scene preview_scene(int width, int height) {
  Scene scene = load_scene(asset_path("scenes/spheres.json"));
  scene.render.width = width;
  scene.render.height = height;
  scene.render.spp = 1;
  PhysicalReference gold, silver;
  gold.roughness = silver.roughness = 0.2f;
  silver.kind = ReferenceKind::silver;
  scene.materials[static_cast<std::size_t>(find_material(scene, "gold"))].reference = gold;
  scene.materials[static_cast<std::size_t>(find_material(scene, "silver"))].reference = silver;
  return scene;
}

void BM_PreviewRayTraced(benchmark::State& state) {
  const Scene scene =
      preview_scene(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  for (auto _ : state) benchmark::DoNotOptimize(render(scene));
}

void BM_PreviewReference(benchmark::State& state) {
  const Scene scene =
      preview_scene(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  ReferenceOptions options;
  options.physical = true;
  options.spp = 1;
  for (auto _ : state) benchmark::DoNotOptimize(render_reference<double>(scene, options));
}

BENCHMARK(BM_PreviewRayTraced)->Args({432, 324})->Args({864, 648})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PreviewReference)->Args({432, 324})->Args({864, 648})->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace gloss
