#include "analysis/bench/bench_scaling.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>

#include <nlohmann/json.hpp>

#include "analysis/bench/paired_timing.h"
#include "analysis/bench/ray_baseline.h"
#include "base/error.h"
#include "base/timing.h"
#include "engine/render_context.h"
#include "engine/shade/pixel_factors.h"
#include "engine/trace/embree_scene.h"
#include "engine/trace/sample_cache.h"
#include "engine/trace/single_sample_pass.h"
#include "io/scene/scene_loader.h"
#include "scene/fields/validation.h"

namespace gloss {

namespace {
using Clock = std::chrono::steady_clock;
constexpr int kTeapotGrid = 7;  // teapots per side of the grid on the floor

// The lights of setup: the scene's first light copied to a g x g grid (g = ceil(sqrt(n))),
// n of its points used, each with 1/n of its colours so the image keeps its brightness. One
// light is the scene's own.
void spread_lights(Scene& scene, int n) {
  if (n == 1 || scene.lights.empty()) return;
  const PointLight light = scene.lights[0];
  const int g = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n))));
  scene.lights.clear();
  for (int k = 0; k < n; ++k) {
    PointLight l = light;
    const float fx = g > 1 ? static_cast<float>(k % g) / static_cast<float>(g - 1) : 0.5f;
    const float fz = g > 1 ? static_cast<float>(k / g) / static_cast<float>(g - 1) : 0.5f;
    // Under the ceiling of the benchmark's box (x, z in [-1, 1]), around the scene's light.
    l.position.x = light.position.x + (fx - 0.5f) * 1.2f;
    l.position.z = light.position.z - fz * 1.1f;
    l.diffuse = light.diffuse / static_cast<float>(n);
    l.specular = light.specular / static_cast<float>(n);
    l.ambient = light.ambient / static_cast<float>(n);
    scene.lights.push_back(l);
  }
}

// The scene's teapots replaced by a kTeapotGrid x kTeapotGrid grid of small ones standing on
// the floor (y = -1) of the benchmark's box, each at tessellation `level`.
Scene teapot_grid(const Scene& scene, int level) {
  nlohmann::json doc = nlohmann::json::parse(scene_to_json_text(scene));
  nlohmann::json objects = nlohmann::json::array();
  nlohmann::json teapot;
  for (const auto& object : doc["objects"]) {
    if (object.value("type", "") == "teapot") {
      teapot = object;
    } else {
      objects.push_back(object);
    }
  }
  if (teapot.is_null()) throw InputError(scene.path, "the scaling rows need a teapot");
  const float step = 2.0f / kTeapotGrid;
  for (int i = 0; i < kTeapotGrid * kTeapotGrid; ++i) {
    nlohmann::json t = teapot;
    t["name"] = "teapot" + std::to_string(i);
    t["position"] = {-1.0f + (static_cast<float>(i % kTeapotGrid) + 0.5f) * step, -1.0f,
                     -1.0f + (static_cast<float>(i / kTeapotGrid) + 0.5f) * step};
    t["scale"] = 0.08f;  // the teapot is about 3.4 units long: 0.27 of the 0.29 step
    t["tessellation"] = level;
    objects.push_back(t);
  }
  doc["objects"] = objects;
  Scene out = parse_scene(doc.dump(), scene.path);
  out.render = scene.render;
  return out;
}

long long triangle_count(const Scene& scene) {
  long long n = 0;
  for (const Object& o : scene.objects) {
    if (o.mesh) n += static_cast<long long>(o.mesh->triangles.size());
  }
  return n;
}
}  // namespace

std::vector<ScalingSetup> scaling_setups() {
  std::vector<ScalingSetup> rows;
  for (int lights : {1, 4, 16, 64}) rows.push_back({lights, 0, 1280, 720});
  // 49 x 64 x level^2: 12,544, 1,016,064 and 10,188,864 triangles, walls aside.
  for (int level : {2, 18, 57}) rows.push_back({1, level, 1280, 720});
  for (const auto& [w, h] : {std::pair{2560, 1440}, std::pair{3840, 2160}}) {
    rows.push_back({1, 0, w, h});
  }
  return rows;
}

Scene scaling_scene(const Scene& base, const ScalingSetup& setup) {
  Scene scene = setup.teapot_level > 0 ? teapot_grid(base, setup.teapot_level) : base;
  spread_lights(scene, setup.lights);
  scene.render.width = setup.width;
  scene.render.height = setup.height;
  scene.render.spp = 1;
  return scene;
}

ScalingPoint run_scaling_row(const Scene& base, const ScalingSetup& setup, int runs) {
  ScalingPoint point;
  point.setup = setup;
  const Clock::time_point start = Clock::now();
  Scene scene;
  try {  // the memory budget gloss-cli render applies: the teapots' reader claims it too
    scene = scaling_scene(base, setup);
    validate_scene(scene);
  } catch (const InputError& e) {
    point.skipped = e.what();
    return point;
  }
  point.triangles = triangle_count(scene);
  const EmbreeScene embree(scene);
  point.build_ms = ms_since(start);
  const RenderContext ctx = make_render_context(scene, embree);
  SampleCache cache;
  PixelFactors factors;
  Image total;
  // The benchmark's retrace: the engine's fused first pass with the total (bench.cpp).
  auto render = [&] {
    reset_sample_cache(cache, scene, setup.width, setup.height, 1);
    trace_single_sample(cache, ctx, factors, &total);
  };
  auto raw = [&] { trace_rays_raw(scene, embree, setup.width, setup.height); };
  const Paired paired = time_paired(runs, render, raw);
  point.retrace_ms = paired.f_ms;
  point.embree_raw_ms = paired.g_ms;
  point.ratio = paired.ratio;
  return point;
}

std::string scaling_point_json_text(const ScalingPoint& p) {
  nlohmann::json j = {{"lights", p.setup.lights},         {"teapot_level", p.setup.teapot_level},
                      {"triangles", p.triangles},         {"width", p.setup.width},
                      {"height", p.setup.height},         {"retrace_ms", p.retrace_ms},
                      {"embree_raw_ms", p.embree_raw_ms}, {"ratio", p.ratio},
                      {"build_ms", p.build_ms},           {"peak_rss_mb", p.peak_rss_mb}};
  if (!p.skipped.empty()) j["skipped"] = p.skipped;
  return j.dump();
}

ScalingPoint parse_scaling_point(const std::string& text) {
  try {
    const nlohmann::json j = nlohmann::json::parse(text);
    ScalingPoint p;
    p.setup = {j.at("lights").get<int>(), j.at("teapot_level").get<int>(), j.at("width").get<int>(),
               j.at("height").get<int>()};
    p.triangles = j.at("triangles").get<long long>();
    p.retrace_ms = j.at("retrace_ms").get<double>();
    p.embree_raw_ms = j.at("embree_raw_ms").get<double>();
    p.ratio = j.at("ratio").get<double>();
    p.build_ms = j.at("build_ms").get<double>();
    p.peak_rss_mb = j.at("peak_rss_mb").get<double>();
    p.skipped = j.value("skipped", "");
    return p;
  } catch (const nlohmann::json::exception& e) {
    throw InputError("scaling row", e.what());
  }
}

std::string scaling_setup_text(const ScalingSetup& s) {
  char text[64];
  std::snprintf(text, sizeof text, "%d,%d,%d,%d", s.lights, s.teapot_level, s.width, s.height);
  return text;
}

ScalingSetup parse_scaling_setup(const std::string& text) {
  ScalingSetup s;
  char end = 0;
  if (std::sscanf(text.c_str(), "%d,%d,%d,%d%c", &s.lights, &s.teapot_level, &s.width, &s.height,
                  &end) != 4 ||
      s.lights < 1 || s.teapot_level < 0 || s.teapot_level > 64 || s.width < 1 || s.height < 1) {
    throw InputError("--scaling-row",
                     "expected LIGHTS,TEAPOT_LEVEL,WIDTH,HEIGHT, got '" + text + "'");
  }
  return s;
}

}  // namespace gloss
