#include "analysis/bench/texture_bench.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>

#include <glm/vec4.hpp>

#include "analysis/bench/paired_timing.h"
#include "analysis/bench/ray_baseline.h"
#include "engine/render_context.h"
#include "engine/shade/pixel_factors.h"
#include "engine/trace/embree_scene.h"
#include "engine/trace/sample_cache.h"
#include "engine/trace/single_sample_pass.h"
#include "texture/mip_pyramid.h"
#include "texture/texel_image.h"

namespace gloss {

namespace {
// A side x side RGBA float map made in memory, each texel's four channels written by
// texel(x, y, rgba); source names it in messages.
template <class Texel>
std::shared_ptr<const Texture> benchmark_map(int side, const char* source, Texel texel) {
  FloatImage image = texel_image(side, side, 4, [&texel](int x, int y) {
    glm::vec4 t(0.0f);
    texel(x, y, &t[0]);
    return t;
  });
  auto texture = std::make_shared<Texture>(make_texture(std::move(image)));
  texture->source = source;
  return texture;
}

// A painted-looking map: tiles of 64 texels in two tones with a hashed speckle on every texel,
// so every level of the pyramid has detail to read.
std::shared_ptr<const Texture> colour_map(int side) {
  return benchmark_map(side, "benchmark colour map", [](int x, int y, float* t) {
    const unsigned h =
        (static_cast<unsigned>(x) * 73856093u) ^ (static_cast<unsigned>(y) * 19349663u);
    const float speckle = static_cast<float>(h % 1024) / 4096.0f;
    const bool tile = ((x / 64) + (y / 64)) % 2 == 0;
    t[0] = (tile ? 0.8f : 0.3f) + speckle;
    t[1] = (tile ? 0.7f : 0.35f) + speckle;
    t[2] = (tile ? 0.6f : 0.5f) + speckle;
    t[3] = 1.0f;
  });
}

// Gentle ripples as a tangent-space normal map (2 c - 1 = the normal).
std::shared_ptr<const Texture> normal_map(int side) {
  return benchmark_map(side, "benchmark normal map", [](int x, int y, float* t) {
    const float nx = 0.3f * std::sin(x * 0.05f), ny = 0.3f * std::sin(y * 0.07f);
    const float nz = std::sqrt(1.0f - nx * nx - ny * ny);
    t[0] = 0.5f * nx + 0.5f;
    t[1] = 0.5f * ny + 0.5f;
    t[2] = 0.5f * nz + 0.5f;
    t[3] = 1.0f;
  });
}

void render_1spp(const Scene& scene, const EmbreeScene& embree, SampleCache& cache,
                 PixelFactors& factors, Image& total) {
  const RenderContext ctx = make_render_context(scene, embree);
  reset_sample_cache(cache, scene, scene.render.width, scene.render.height, 1);
  trace_single_sample(cache, ctx, factors, &total);
}
}  // namespace

Scene with_benchmark_maps(const Scene& scene, int side) {
  Scene out = scene;
  const std::shared_ptr<const Texture> colour = colour_map(side), normals = normal_map(side);
  std::vector<bool> on_quad(out.materials.size(), false);
  for (const Object& o : out.objects) {
    if (o.type == ObjectType::quad && o.material >= 0) on_quad[o.material] = true;
  }
  for (std::size_t m = 0; m < out.materials.size(); ++m) {
    TextureMap& diffuse = out.materials[m].map(MapSlot::diffuse);
    diffuse.file = "benchmark-colour.png";
    diffuse.texture = colour;
    if (!on_quad[m]) continue;
    TextureMap& normal = out.materials[m].map(MapSlot::normal);
    normal.file = "benchmark-normals.png";
    normal.texture = normals;
  }
  return out;
}

void measure_textured(const Scene& scene, const BenchOptions& options, BenchReport& report) {
  const Scene textured = with_benchmark_maps(scene);
  const EmbreeScene embree(scene), textured_embree(textured);
  SampleCache cache, textured_cache;
  PixelFactors factors, textured_factors;
  Image total, textured_total;
  const int runs = std::max(15, 2 * options.runs);
  const Paired retrace = time_paired(
      runs,
      [&] {
        render_1spp(textured, textured_embree, textured_cache, textured_factors, textured_total);
      },
      [&] { render_1spp(scene, embree, cache, factors, total); });
  report.textured_retrace_ms = retrace.f_ms;
  report.textured_retrace_ratio = retrace.ratio;

  // kd edits, total image only: textured against untextured, both from their 1-spp caches.
  Scene edited = scene, textured_edited = textured;
  for (Material& m : edited.materials) m.diffuse *= 0.9f;
  for (Material& m : textured_edited.materials) m.diffuse *= 0.9f;
  const RenderContext ctx = make_render_context(edited, embree);
  const RenderContext textured_ctx = make_render_context(textured_edited, textured_embree);
  TermImages a, b;
  const int short_runs = std::max(15, 3 * options.runs);
  const Paired reshade = time_paired(
      short_runs, [&] { combine_terms(textured_factors, textured_ctx, a, false); },
      [&] { combine_terms(factors, ctx, b, false); });
  report.textured_reshade_ms = reshade.f_ms;
  report.textured_reshade_ratio = reshade.ratio;
  const std::size_t pixels = static_cast<std::size_t>(scene.render.width) * scene.render.height;
  const std::size_t read =
      textured_factors.bytes() + textured_factors.texel_channels * pixels * sizeof(float);
  report.textured_cache_bytes_per_pixel = static_cast<double>(read) / pixels;
  StreamingPass stream(read, pixels * sizeof(glm::vec3));
  report.textured_bandwidth_floor_ms =
      time_paired(
          short_runs, [&] { stream.run(); },
          [&] { combine_terms(textured_factors, textured_ctx, a, false); })
          .f_ms;
}

}  // namespace gloss
