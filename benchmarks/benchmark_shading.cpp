// Micro-benchmarks of the shading kernel and the re-shade paths (built by default, not tests):
//   ./build/benchmarks/gloss_benchmarks
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "base/assets.h"
#include "engine/parallel_loops.h"
#include "engine/render_context.h"
#include "engine/shade/pixel_factors.h"
#include "engine/shade/power_lanes.h"
#include "engine/trace/embree_scene.h"
#include "engine/trace/sample_cache.h"
#include "engine/trace/single_sample_pass.h"
#include "io/scene/scene_loader.h"
#include "shading/shading.h"

namespace gloss {
namespace {

// light_factors + specular_power over random unit normals and lights facing them.
void BM_ShadingKernel(benchmark::State& state) {
  const float alpha = static_cast<float>(state.range(0));
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  std::vector<glm::vec3> normals(4096);
  for (glm::vec3& n : normals) n = glm::normalize(glm::vec3(u(rng), u(rng), 1.5f));
  const glm::vec3 p(0.0f), v(0.0f, 0.0f, 1.0f), light(1.0f, 2.0f, 3.0f), att(1.0f, 0.0f, 0.0f);
  const DenormalsOff denormals_off;  // as in the render threads
  for (auto _ : state) {
    float sum = 0.0f;
    for (const glm::vec3& n : normals) {
      const LightFactors<float> f = light_factors<float>(p, n, v, light, att, true, 1.0f);
      sum += f.diffuse_weight + f.spec_weight * specular_power(f.cos_phong, alpha);
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<long long>(normals.size()));
}
BENCHMARK(BM_ShadingKernel)->Arg(32)->Arg(1000000);

// The renderer's c^alpha over 16-lane runs (power_lanes.h): range(0) alpha, range(1) 1 = fast.
void BM_PowerLanes(benchmark::State& state) {
  Scene scene;
  Material m;
  m.shininess = static_cast<float>(state.range(0));
  scene.materials.push_back(m);
  const MaterialExponents exponents = material_exponents(scene);
  const PowMode mode = state.range(1) != 0 ? PowMode::fast : PowMode::exact;
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<float> c(4096), out(4096);
  for (float& x : c) x = u(rng);
  const std::int32_t material[kLanes] = {};
  const DenormalsOff denormals_off;  // as in the render threads
  for (auto _ : state) {
    for (std::size_t i = 0; i < c.size(); i += kLanes) {
      specular_power_lanes(exponents, material, &c[i], &out[i], kLanes, mode);
    }
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<long long>(c.size()));
}
BENCHMARK(BM_PowerLanes)->Args({32, 0})->Args({1000000, 0})->Args({32, 1})->Args({1000000, 1});

// The cached state of the benchmark scene at 640x360, 1 spp, built once.
struct Cached {
  Scene scene;
  std::unique_ptr<EmbreeScene> embree;
  SampleCache cache;
  PixelFactors factors;

  Cached() {
    scene = load_scene(asset_path("scenes/cornell-teapot.json"));
    scene.render.width = 640;
    scene.render.height = 360;
    scene.render.spp = 1;
    embree = std::make_unique<EmbreeScene>(scene);
    const RenderContext ctx = context();
    cache = make_sample_cache(scene, 640, 360, 1);
    add_samples(cache, ctx, 1);
    build_pixel_factors(cache, ctx, factors);
  }
  RenderContext context() const { return make_render_context(scene, *embree); }
};

Cached& cached() {
  static Cached c;  // built once for all benchmarks of this binary
  return c;
}

// A material-constant edit: recombination only (range(0): 1 = also the four term images).
void BM_ReshadeConstants(benchmark::State& state) {
  Cached& c = cached();
  const RenderContext ctx = c.context();
  TermImages out;
  for (auto _ : state) {
    combine_terms(c.factors, ctx, out, state.range(0) != 0);
    benchmark::DoNotOptimize(out.total.pixels.data());
  }
  state.SetItemsProcessed(state.iterations() * 640 * 360);
}
BENCHMARK(BM_ReshadeConstants)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

// A shininess edit: per-pixel factors re-summed from the per-sample cosines, then recombined.
void BM_ReshadeExponent(benchmark::State& state) {
  Cached& c = cached();
  Scene scene = c.scene;
  for (Material& m : scene.materials) m.shininess = static_cast<float>(state.range(0));
  RenderContext ctx = c.context();
  ctx.scene = &scene;
  PixelFactors factors;
  TermImages out;
  for (auto _ : state) {
    build_pixel_factors(c.cache, ctx, factors);
    combine_terms(factors, ctx, out, false);
    benchmark::DoNotOptimize(out.total.pixels.data());
  }
  state.SetItemsProcessed(state.iterations() * 640 * 360);
}
BENCHMARK(BM_ReshadeExponent)->Arg(32)->Arg(1000000)->Unit(benchmark::kMicrosecond);

// The engine's first full-resolution pass: trace, light factors and pixel factors, fused.
void BM_FirstPass(benchmark::State& state) {
  Cached& c = cached();
  const RenderContext ctx = c.context();
  SampleCache cache = make_sample_cache(c.scene, 640, 360, 1);
  PixelFactors factors;
  for (auto _ : state) {
    reset_sample_cache(cache, c.scene, 640, 360, 1);
    trace_single_sample(cache, ctx, factors);
    benchmark::DoNotOptimize(factors.specular.data());
  }
  state.SetItemsProcessed(state.iterations() * 640 * 360);
}
BENCHMARK(BM_FirstPass)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace gloss

BENCHMARK_MAIN();
