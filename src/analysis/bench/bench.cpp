#include "analysis/bench/bench.h"

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <utility>

#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/task_arena.h>
#include <nlohmann/json.hpp>

#include "analysis/bench/bench_render.h"
#include "analysis/bench/bench_table.h"
#include "analysis/bench/paired_timing.h"
#include "analysis/bench/ray_baseline.h"
#include "analysis/bench/texture_bench.h"
#include "analysis/image/image_metrics.h"
#include "base/timing.h"
#include "engine/environment/environment_stage.h"
#include "engine/progressive_renderer.h"
#include "engine/render_context.h"
#include "engine/renderer.h"
#include "engine/shade/pixel_factors.h"
#include "engine/trace/embree_scene.h"
#include "engine/trace/sample_cache.h"
#include "engine/trace/single_sample_pass.h"
#include "io/scene/scene_loader.h"

namespace gloss {

void full_render(const Scene& scene, const EmbreeScene& embree, SampleCache& cache,
                 PixelFactors& factors, TermImages& out, bool terms) {
  const RenderContext ctx = make_render_context(scene, embree);
  reset_sample_cache(cache, scene, scene.render.width, scene.render.height, 1);
  if (terms) {
    trace_single_sample(cache, ctx, factors);
    environment_sky(cache, ctx, factors);  // the environment as the background (else nothing)
    combine_terms(factors, ctx, out, true);
  } else {
    trace_single_sample(cache, ctx, factors, &out.total);  // the total made in the same pass
  }
}

namespace {
using Clock = std::chrono::steady_clock;

double peak_rss_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
}

struct EngineTimes {
  double first_ms = 0, converged_ms = 0;  // medians
  double ratio = 0;  // median of converged / baseline within pairs (0 without a baseline)
};

// From a camera change to the first published pass and to convergence, in the engine, with
// options.converge_spp samples spent as `sampling` says. Given a baseline, each convergence is
// paired with a timed run of it (as time_paired does).
EngineTimes measure_engine(const Scene& base, const BenchOptions& options, Sampling sampling,
                           const std::function<void()>& baseline = nullptr) {
  Scene scene = base;
  scene.render.spp = options.converge_spp;
  scene.render.sampling = sampling;
  ProgressiveOptions total_only;  // the viewport's default view: the total image only
  total_only.terms = false;
  ProgressiveRenderer engine(total_only);
  std::mutex mutex;
  std::condition_variable cv;
  std::uint64_t generation = 0;
  double first = -1, converged = -1;
  engine.set_on_publish([&] {
    const auto frame = engine.latest();
    std::lock_guard<std::mutex> lock(mutex);
    if (frame->info.generation != generation) return;
    if (first < 0) first = frame->info.since_change_ms;
    if (frame->info.converged) converged = frame->info.since_change_ms;
    cv.notify_all();
  });
  std::vector<double> firsts, converges, ratios;
  for (int run = 0; run <= options.runs; ++run) {
    scene.camera = orbit_camera(base.camera, run % 2 == 0 ? 2.0f : -2.0f, 0.0f);
    {
      std::unique_lock<std::mutex> lock(mutex);
      ++generation;
      first = converged = -1;
    }
    engine.set_scene(scene);
    std::unique_lock<std::mutex> lock(mutex);
    cv.wait(lock, [&] { return converged >= 0; });
    if (run > 0) {  // run 0 warms up (first Embree build of this scene)
      firsts.push_back(first);
      converges.push_back(converged);
    }
    lock.unlock();
    if (baseline && run > 0) {
      const Clock::time_point start = Clock::now();
      baseline();
      ratios.push_back(converges.back() / ms_since(start));
    }
  }
  engine.set_on_publish(nullptr);
  return {median(firsts), median(converges), ratios.empty() ? 0.0 : median(ratios)};
}

// Adaptive against uniform sampling at converge_spp, both against a uniform reference_spp
// render (the fast renderer: the reference of the sampling, not of the arithmetic).
void measure_aa_quality(const Scene& base, const BenchOptions& options, BenchReport& report) {
  Scene scene = base;
  RenderOptions total_only;
  total_only.terms = false;
  scene.render.sampling = Sampling::uniform;
  scene.render.spp = options.reference_spp;
  const Image reference = render(scene, total_only).total;
  scene.render.spp = options.converge_spp;
  report.uniform_rmse = compare_images(render(scene, total_only).total, reference).rmse;
  scene.render.sampling = Sampling::adaptive;
  std::vector<std::uint32_t> refined;
  RenderOptions adaptive = total_only;
  adaptive.refined = &refined;
  report.aa_rmse = compare_images(render(scene, adaptive).total, reference).rmse;
  report.aa_rmse_ratio = report.aa_rmse / report.uniform_rmse;
  report.aa_refined_share = static_cast<double>(refined.size()) /
                            (static_cast<double>(base.render.width) * base.render.height);
}

}  // namespace

BenchReport run_benchmark(const Scene& input, const BenchOptions& options) {
  BenchReport report;
  Scene scene = input;
  scene.render.width = options.width;
  scene.render.height = options.height;
  scene.render.spp = 1;
  report.scene = scene.path;
  report.width = options.width;
  report.height = options.height;
  report.threads = tbb::this_task_arena::max_concurrency();
  const std::size_t pixels = static_cast<std::size_t>(options.width) * options.height;

  const EmbreeScene embree(scene);
  SampleCache cache;
  PixelFactors factors;
  TermImages out;

  const Paired retrace = time_paired(
      std::max(15, 2 * options.runs),  // short pairs: more of them, a steadier ratio
      [&] { full_render(scene, embree, cache, factors, out, false); },
      [&] {
        report.rays_per_frame = trace_rays_raw(scene, embree, options.width, options.height);
      });
  report.retrace_ms = retrace.f_ms;
  report.embree_raw_ms = retrace.g_ms;
  report.retrace_ratio = retrace.ratio;
  report.retrace_terms_ms =
      time_median(options.runs, [&] { full_render(scene, embree, cache, factors, out, true); });
  full_render(scene, embree, cache, factors, out, false);  // the 1-spp caches, for the edits
  report.cache_bytes_per_pixel = static_cast<double>(factors.bytes()) / pixels;
  report.sample_cache_bytes_per_sample = static_cast<double>(cache.bytes()) / pixels;

  // Material edit: recombination only, into the frame the viewport shows (total).
  Scene edited = scene;
  for (Material& m : edited.materials) m.diffuse *= 0.9f;
  const RenderContext edited_ctx = make_render_context(edited, embree);
  TermImages reshaded;
  StreamingPass stream(factors.bytes(), pixels * sizeof(glm::vec3));
  const int short_runs = std::max(15, 3 * options.runs);  // shorter still: more samples
  const Paired reshade = time_paired(
      short_runs, [&] { combine_terms(factors, edited_ctx, reshaded, false); },
      [&] { stream.run(); });
  report.reshade_ms = reshade.f_ms;
  report.bandwidth_floor_ms = reshade.g_ms;
  report.reshade_ratio = reshade.ratio;
  report.reshade_terms_ms =
      time_median(short_runs, [&] { combine_terms(factors, edited_ctx, reshaded, true); });

  // Shininess edit: re-sum the per-sample cosines, then recombine; alpha 32 against 1e6.
  for (float alpha : {32.0f, 1e6f}) {
    Scene shiny = scene;
    for (Material& m : shiny.materials) m.shininess = alpha;
    const RenderContext ctx = make_render_context(shiny, embree);
    const double t = time_median(options.runs, [&] {
      build_pixel_factors(cache, ctx, factors);
      combine_terms(factors, ctx, reshaded, false);
    });
    (alpha == 32.0f ? report.exponent_ms_alpha32 : report.exponent_ms_alpha1e6) = t;
  }

  // Light move: shadow rays and factors from the cached primary hits.
  Scene moved = scene;
  if (!moved.lights.empty()) {
    moved.lights[0].position += glm::vec3(0.05f, 0.0f, 0.0f);
    const RenderContext ctx = make_render_context(moved, embree);
    report.light_move_ms = time_median(options.runs, [&] {
      // The engine's path for a 1-spp image: factors and total in one pass.
      relight_single_sample(cache, ctx, factors, &reshaded.total);
    });
  }

  // One thread, then all threads again right after. Not alternated: full renders timed right
  // after one-thread arena runs read markedly slower than the same renders timed on their own
  // (docs/engine.md, "Benchmark timing").
  tbb::task_arena single(1);
  report.single_thread_ms = time_median(options.runs, [&] {
    single.execute([&] { full_render(scene, embree, cache, factors, out, false); });
  });
  const double all_threads_ms =
      time_median(options.runs, [&] { full_render(scene, embree, cache, factors, out, false); });
  report.threads_speedup = report.single_thread_ms / all_threads_ms;

  const EngineTimes uniform = measure_engine(scene, options, Sampling::uniform);
  report.first_preview_ms = uniform.first_ms;
  report.converge_16spp_ms = uniform.converged_ms;
  // Paired with the 1-spp full render, as the retrace ratio is: a shared machine's speed drifts.
  const EngineTimes adaptive = measure_engine(scene, options, Sampling::adaptive, [&] {
    full_render(scene, embree, cache, factors, out, false);
  });
  report.aa_ms = adaptive.converged_ms;
  report.aa_ratio = adaptive.ratio;
  measure_aa_quality(scene, options, report);

  if (has_object_type(scene, ObjectType::teapot)) {
    for (int level : options.tessellation_levels) {
      TessellationPoint point;
      point.level = level;
      const Clock::time_point start = Clock::now();
      const Scene tess = with_teapot_tessellation(scene, level);
      const EmbreeScene tess_embree(tess);
      point.build_ms = ms_since(start);
      for (const Object& o : tess.objects) {
        if (o.type == ObjectType::teapot && o.mesh)
          point.triangles += static_cast<long long>(o.mesh->triangles.size());
      }
      point.render_ms = time_median(std::max(3, options.runs / 2), [&] {
        full_render(tess, tess_embree, cache, factors, out, false);
      });
      report.tessellation.push_back(point);
    }
  }
  measure_textured(scene, options, report);
  report.bench_peak_rss_mb = peak_rss_mb();
  return report;
}

std::string format_bench_table(const BenchReport& r) {
  BenchTable table;
  table.line("gloss bench: %s at %dx%d, %d threads (medians)\n", r.scene.c_str(), r.width, r.height,
             r.threads);
  table.row("retrace_ms", r.retrace_ms, "ms", "full 1-spp render (trace + shade + total image)");
  table.row("embree_raw_ms", r.embree_raw_ms, "ms", "same primary + shadow rays, no shading");
  table.row("retrace_ratio", r.retrace_ratio, "", "over the Embree baseline; target <= 1.2");
  table.row("retrace_terms_ms", r.retrace_terms_ms, "ms",
            "the same + the 4 term images (term view)");
  table.row("rays_per_frame", static_cast<double>(r.rays_per_frame), "", "");
  table.row("reshade_ms", r.reshade_ms, "ms", "material edit, total image; target <= 3");
  table.row("bandwidth_floor_ms", r.bandwidth_floor_ms, "ms", "streaming the same bytes");
  table.row("reshade_ratio", r.reshade_ratio, "", "target <= 2");
  table.row("reshade_terms_ms", r.reshade_terms_ms, "ms", "material edit, total + 4 term images");
  table.row("exponent_ms_alpha32", r.exponent_ms_alpha32, "ms", "shininess edit to 32");
  table.row("exponent_ms_alpha1e6", r.exponent_ms_alpha1e6, "ms", "shininess edit to 1e6");
  table.row("light_move_ms", r.light_move_ms, "ms", "shadow rays + re-shade");
  table.row("first_preview_ms", r.first_preview_ms, "ms",
            "camera change to first pass; target <= 10");
  table.row("converge_16spp_ms", r.converge_16spp_ms, "ms", "camera change to 16 spp, uniform");
  table.row("aa_ms", r.aa_ms, "ms", "camera change to 16 spp, adaptive");
  table.row("aa_ratio", r.aa_ratio, "", "over a full 1-spp render, paired runs; target <= 2");
  table.row("aa_rmse_ratio", r.aa_rmse_ratio, "",
            "adaptive RMSE / uniform's (256 spp ref); target <= 1");
  table.row("aa_refined_share", r.aa_refined_share, "",
            "share of pixels adaptive sampling refined");
  table.row("aa_rmse", r.aa_rmse, "", "adaptive 16 spp against uniform 256 spp");
  table.row("uniform_rmse", r.uniform_rmse, "", "uniform 16 spp against uniform 256 spp");
  table.row("single_thread_ms", r.single_thread_ms, "ms", "full render on 1 thread");
  table.row("threads_speedup", r.threads_speedup, "x", "target >= 1.7");
  table.row("cache_bytes_per_pixel", r.cache_bytes_per_pixel, "B", "per-pixel factors");
  table.row("sample_cache_bytes_per_sample", r.sample_cache_bytes_per_sample, "B",
            "per-sample cache");
  table.row("textured_retrace_ms", r.textured_retrace_ms, "ms",
            "2048^2 maps everywhere, normals on quads");
  table.row("textured_retrace_ratio", r.textured_retrace_ratio, "",
            "over the untextured; target <= 1.3");
  table.row("textured_reshade_ms", r.textured_reshade_ms, "ms", "kd edit on the textured scene");
  table.row("textured_reshade_ratio", r.textured_reshade_ratio, "",
            "over today's re-shade; target <= 1.5");
  table.row("textured_bandwidth_floor_ms", r.textured_bandwidth_floor_ms, "ms",
            "streaming the textured re-shade's bytes");
  table.row("textured_cache_bytes_per_pixel", r.textured_cache_bytes_per_pixel, "B",
            "what the textured re-shade reads");
  if (r.peak_rss_mb > 0) table.row("peak_rss_mb", r.peak_rss_mb, "MB", "plain render, own process");
  table.row("bench_peak_rss_mb", r.bench_peak_rss_mb, "MB", "this benchmark's process");
  if (!r.tessellation.empty()) {
    table.text += "  teapot tessellation: level, triangles, render_ms, build_ms\n";
    for (const TessellationPoint& p : r.tessellation) {
      table.line("    %6d %10lld %10.3f %10.3f\n", p.level, p.triangles, p.render_ms, p.build_ms);
    }
  }
  if (!r.scaling.empty()) {
    table.text +=
        "  scaling, one factor at a time (own process per row): lights, triangles, size,\n"
        "  retrace_ms, embree_raw_ms, ratio, peak_rss_mb\n";
    for (const ScalingPoint& p : r.scaling) {
      if (!p.skipped.empty()) {
        table.line("    %3d %10lld %5dx%-5d skipped: %s\n", p.setup.lights, p.triangles,
                   p.setup.width, p.setup.height, p.skipped.c_str());
      } else {
        table.line("    %3d %10lld %5dx%-5d %9.2f %9.2f %7.3f %8.1f\n", p.setup.lights, p.triangles,
                   p.setup.width, p.setup.height, p.retrace_ms, p.embree_raw_ms, p.ratio,
                   p.peak_rss_mb);
      }
    }
  }
  if (r.environment) table.text += format_environment_bench_table(*r.environment);
  return table.text;
}

std::string bench_to_json(const BenchReport& r) {
  nlohmann::json j;
  j["scene"] = r.scene;
  j["width"] = r.width;
  j["height"] = r.height;
  j["threads"] = r.threads;
  j["retrace_ms"] = r.retrace_ms;
  j["embree_raw_ms"] = r.embree_raw_ms;
  j["retrace_ratio"] = r.retrace_ratio;
  j["retrace_terms_ms"] = r.retrace_terms_ms;
  j["rays_per_frame"] = r.rays_per_frame;
  j["reshade_ms"] = r.reshade_ms;
  j["bandwidth_floor_ms"] = r.bandwidth_floor_ms;
  j["reshade_ratio"] = r.reshade_ratio;
  j["reshade_terms_ms"] = r.reshade_terms_ms;
  j["exponent_ms_alpha32"] = r.exponent_ms_alpha32;
  j["exponent_ms_alpha1e6"] = r.exponent_ms_alpha1e6;
  j["light_move_ms"] = r.light_move_ms;
  j["first_preview_ms"] = r.first_preview_ms;
  j["converge_16spp_ms"] = r.converge_16spp_ms;
  j["aa_ms"] = r.aa_ms;
  j["aa_ratio"] = r.aa_ratio;
  j["aa_rmse_ratio"] = r.aa_rmse_ratio;
  j["aa_refined_share"] = r.aa_refined_share;
  j["aa_rmse"] = r.aa_rmse;
  j["uniform_rmse"] = r.uniform_rmse;
  j["single_thread_ms"] = r.single_thread_ms;
  j["threads_speedup"] = r.threads_speedup;
  j["cache_bytes_per_pixel"] = r.cache_bytes_per_pixel;
  j["sample_cache_bytes_per_sample"] = r.sample_cache_bytes_per_sample;
  j["textured_retrace_ms"] = r.textured_retrace_ms;
  j["textured_retrace_ratio"] = r.textured_retrace_ratio;
  j["textured_reshade_ms"] = r.textured_reshade_ms;
  j["textured_reshade_ratio"] = r.textured_reshade_ratio;
  j["textured_bandwidth_floor_ms"] = r.textured_bandwidth_floor_ms;
  j["textured_cache_bytes_per_pixel"] = r.textured_cache_bytes_per_pixel;
  j["peak_rss_mb"] = r.peak_rss_mb;
  j["bench_peak_rss_mb"] = r.bench_peak_rss_mb;
  nlohmann::json tess = nlohmann::json::array();
  for (const TessellationPoint& p : r.tessellation) {
    tess.push_back({{"level", p.level},
                    {"triangles", p.triangles},
                    {"render_ms", p.render_ms},
                    {"build_ms", p.build_ms}});
  }
  j["tessellation"] = tess;
  if (!r.scaling.empty()) {
    nlohmann::json rows = nlohmann::json::array();
    for (const ScalingPoint& p : r.scaling) {
      rows.push_back(nlohmann::json::parse(scaling_point_json_text(p)));
    }
    j["scaling"] = rows;
  }
  if (r.environment)
    j["environment"] = nlohmann::json::parse(environment_bench_json(*r.environment));
  return j.dump(2) + "\n";
}

}  // namespace gloss
