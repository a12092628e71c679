// gloss_raster_bench [SCENE] [--width N] [--height N] [--runs N]: the raster path's frame against
// the ray tracer's full 1-spp re-trace, side by side in one process (issue 12, Speed), through
// EGL without a display. Default: the scene gloss-cli bench uses (cornell-teapot.json) at
// 1280x720, 15 pairs per row.
//
// The CPU baseline is the engine's re-trace after a camera move, as gloss-cli bench's retrace_ms
// (analysis/bench/bench.cpp): BVH kept, primary and shadow rays, shading and the total image in one
// pass, 1 spp. Also printed: render() at 1 spp, which builds the BVH too. Each raster row is timed
// in pairs with the re-trace (raster frame, re-trace, raster frame, ...), and its ratio is the
// median of the ratios within pairs, as bench.cpp's time_paired does: a shared machine's speed
// drifts over minutes and a pair sees the same state of it. Raster frames keep their meshes and
// shadow maps (a camera drag) except the "light drag" row, whose light moves by 1e-3 every frame
// so that each frame redraws the shadow maps. Built by default, not run by ctest except once at
// a tiny size (tests/CMakeLists.txt): the full run takes about 5 s here, but its figures mean
// something only on a quiet machine, not beside other tests under ctest -j.
#include <glad/gl.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include <tbb/info.h>

#include "base/assets.h"
#include "base/timing.h"
#include "editor/gl/egl_context.h"
#include "editor/gl/raster/raster_renderer.h"
#include "engine/render_context.h"
#include "engine/renderer.h"
#include "engine/shade/pixel_factors.h"
#include "engine/trace/embree_scene.h"
#include "engine/trace/sample_cache.h"
#include "engine/trace/single_sample_pass.h"
#include "io/scene/scene_loader.h"

namespace gloss {
namespace {

using Clock = std::chrono::steady_clock;

struct Args {
  std::string scene;
  int width = 1280, height = 720, runs = 15;
};

struct RasterVariant {
  const char* name;
  ShadingFrequency shading;
  bool shadows;
  bool terms;       // the four term images read back too
  bool move_light;  // every frame redraws the shadow maps
};

// Medians of one row: the raster frame's wall time and phases, the paired re-trace, the ratios.
struct Row {
  double wall_ms = 0, upload_ms = 0, shadow_ms = 0, draw_ms = 0, readback_ms = 0;
  double cpu_ms = 0, ratio = 0, ratio_no_readback = 0;
};

Row measure(RasterRenderer& raster, Scene scene, const RasterVariant& v, int runs,
            const std::function<void()>& retrace) {
  scene.render.shadows = v.shadows;
  RasterSettings settings;
  settings.shading = v.shading;
  const float light_x = scene.lights.empty() ? 0.0f : scene.lights[0].position.x;
  int frame_number = 0;
  auto frame = [&]() {
    if (v.move_light && !scene.lights.empty()) {
      scene.lights[0].position.x = light_x + ((frame_number++ % 2) != 0 ? 1e-3f : -1e-3f);
    }
    const Clock::time_point start = Clock::now();
    raster.render(scene, settings, v.terms);
    return ms_since(start);
  };
  frame();  // warm-up: meshes uploaded, shadow maps drawn, programs first used
  frame();
  retrace();
  std::vector<double> wall, upload, shadow, draw, readback, cpu, ratio, ratio_no_readback;
  for (int i = 0; i < runs; ++i) {
    wall.push_back(frame());
    const RasterTiming& t = raster.timing();
    upload.push_back(t.upload_ms);
    shadow.push_back(t.shadow_ms);
    draw.push_back(t.draw_ms);
    readback.push_back(t.readback_ms);
    const Clock::time_point start = Clock::now();
    retrace();
    cpu.push_back(ms_since(start));
    ratio.push_back(wall.back() / cpu.back());
    ratio_no_readback.push_back((wall.back() - readback.back()) / cpu.back());
  }
  return {median(wall),     median(upload), median(shadow), median(draw),
          median(readback), median(cpu),    median(ratio),  median(ratio_no_readback)};
}

bool parse_args(int argc, char** argv, Args& args) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto number = [&](int& out) {
      if (i + 1 >= argc) return false;
      out = std::atoi(argv[++i]);
      return out > 0;
    };
    if (a == "--width") {
      if (!number(args.width)) return false;
    } else if (a == "--height") {
      if (!number(args.height)) return false;
    } else if (a == "--runs") {
      if (!number(args.runs)) return false;
    } else if (!a.empty() && a[0] != '-' && args.scene.empty()) {
      args.scene = a;
    } else {
      return false;
    }
  }
  return true;
}

int run(const Args& args) {
  test::EglContext context;
  if (!context.ok()) {
    std::fprintf(stderr, "gloss_raster_bench: no EGL surfaceless GL: %s\n",
                 context.error().c_str());
    return 1;
  }
  const std::string path =
      args.scene.empty() ? asset_path("scenes/cornell-teapot.json") : args.scene;
  Scene scene = load_scene(path);
  scene.render.width = args.width;
  scene.render.height = args.height;
  scene.render.spp = 1;

  // The CPU re-trace, as bench.cpp's full_render without terms.
  const EmbreeScene embree(scene);
  SampleCache cache;
  PixelFactors factors;
  TermImages out;
  const auto retrace = [&]() {
    const RenderContext ctx = make_render_context(scene, embree);
    reset_sample_cache(cache, scene, scene.render.width, scene.render.height, 1);
    trace_single_sample(cache, ctx, factors, &out.total);
  };
  RenderOptions total_only;
  total_only.terms = false;
  render(scene, total_only);
  std::vector<double> render_ms;
  for (int i = 0; i < args.runs; ++i) {
    const Clock::time_point start = Clock::now();
    render(scene, total_only);
    render_ms.push_back(ms_since(start));
  }

  RasterRenderer raster;
  std::printf(
      "gloss_raster_bench: %s at %dx%d, %d pairs per row (medians), GL: %s, %d TBB threads\n",
      path.c_str(), args.width, args.height, args.runs,
      reinterpret_cast<const char*>(glGetString(GL_RENDERER)), tbb::info::default_concurrency());
  std::printf("  cpu render() at 1 spp, BVH build included: %.2f ms\n", median(render_ms));
  std::printf("  %-36s %8s %7s %7s %7s %8s | %9s %7s %9s\n", "raster frame", "wall_ms", "upload",
              "shadow", "draw", "readback", "retrace", "ratio", "no_rdback");
  const RasterVariant variants[] = {
      {"pixel, shadows on, total", ShadingFrequency::pixel, true, false, false},
      {"pixel, shadows on, total + 4 terms", ShadingFrequency::pixel, true, true, false},
      {"pixel, shadows off, total", ShadingFrequency::pixel, false, false, false},
      {"vertex, shadows on, total", ShadingFrequency::vertex, true, false, false},
      {"vertex, shadows off, total", ShadingFrequency::vertex, false, false, false},
      {"pixel, shadows on, light drag", ShadingFrequency::pixel, true, false, true},
  };
  for (const RasterVariant& v : variants) {
    const Row r = measure(raster, scene, v, args.runs, retrace);
    std::printf("  %-36s %8.2f %7.2f %7.2f %7.2f %8.2f | %9.2f %7.3f %9.3f\n", v.name, r.wall_ms,
                r.upload_ms, r.shadow_ms, r.draw_ms, r.readback_ms, r.cpu_ms, r.ratio,
                r.ratio_no_readback);
    std::fflush(stdout);
  }
  std::printf(
      "  ratio: raster wall time / cpu re-trace (median of pairs); no_rdback: the same without "
      "the read-back phase\n");
  return 0;
}

}  // namespace
}  // namespace gloss

int main(int argc, char** argv) {
  gloss::Args args;
  if (!gloss::parse_args(argc, argv, args)) {
    std::fprintf(stderr, "usage: gloss_raster_bench [SCENE] [--width N] [--height N] [--runs N]\n");
    return 2;
  }
  try {
    return gloss::run(args);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "gloss_raster_bench: %s\n", e.what());
    return 1;
  }
}
