// The glTF export's cost (issue 26: the default scene under a second, fits included):
//   ./build/benchmarks/gloss_benchmarks --benchmark_filter='Export|LoadDefault'
// BM_ExportDefaultScene fits every material (glTF, three.js, the round trip) and writes the
// .glb; BM_LoadDefaultScene, the baseline in the same run, reads the scene file it starts from.
#include <filesystem>

#include <benchmark/benchmark.h>

#include "base/assets.h"
#include "export/gltf_export.h"
#include "export/material_conversion.h"
#include "io/scene/scene_loader.h"

namespace gloss {
namespace {

void BM_LoadDefaultScene(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(load_scene(asset_path("scenes/spheres.json")));
}
BENCHMARK(BM_LoadDefaultScene)->Unit(benchmark::kMillisecond);

void BM_ExportDefaultScene(benchmark::State& state) {
  const Scene scene = load_scene(asset_path("scenes/spheres.json"));
  const std::string path =
      (std::filesystem::temp_directory_path() / "gloss-benchmark-export.glb").string();
  for (auto _ : state) export_gltf(scene, convert_materials(scene), path);
  std::filesystem::remove(path);
}
BENCHMARK(BM_ExportDefaultScene)->Unit(benchmark::kMillisecond);

// The fits of one material alone (gold, as the default scene has it).
void BM_ConvertGold(benchmark::State& state) {
  const Scene scene = load_scene(asset_path("scenes/spheres.json"));
  const Material& gold = scene.materials[static_cast<std::size_t>(find_material(scene, "gold"))];
  for (auto _ : state) {
    benchmark::DoNotOptimize(convert_material("gold", gold, scene.render.model, false));
  }
}
BENCHMARK(BM_ConvertGold)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace gloss
