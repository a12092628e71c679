// The progressive engine from a camera change to convergence at 16 spp, adaptive or uniform
// (what `gloss-cli bench` reports as aa_ms and converge_16spp_ms), for profiling the passes.
#include <benchmark/benchmark.h>

#include <condition_variable>
#include <cstdint>
#include <mutex>

#include "benchmark_scene.h"
#include "engine/progressive_renderer.h"

namespace gloss {
namespace {

// range(0): 1 = adaptive (registered: aa_ms's case), 0 = uniform (converge_16spp_ms's, slow).
void BM_CameraChangeTo16spp(benchmark::State& state) {
  Scene scene = benchmark_scene_720p();
  scene.render.spp = 16;
  scene.render.sampling = state.range(0) != 0 ? Sampling::adaptive : Sampling::uniform;
  ProgressiveOptions options;
  options.terms = false;
  ProgressiveRenderer engine(options);
  std::mutex mutex;
  std::condition_variable cv;
  engine.set_on_publish([&] {  // wakes the wait below, which reads the latest frame itself
    std::lock_guard<std::mutex> lock(mutex);
    cv.notify_all();
  });
  const glm::vec3 eye = scene.camera.eye;
  int run = 0;
  for (auto _ : state) {
    scene.camera.eye = eye + glm::vec3(run++ % 2 == 0 ? 0.01f : -0.01f, 0.0f, 0.0f);
    const std::uint64_t generation = engine.set_scene(scene);
    std::unique_lock<std::mutex> lock(mutex);
    cv.wait(lock, [&] {
      const auto frame = engine.latest();
      return frame && frame->info.converged && frame->info.generation == generation;
    });
  }
  engine.set_on_publish(nullptr);
}
BENCHMARK(BM_CameraChangeTo16spp)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace gloss
