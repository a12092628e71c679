#include "engine/renderer.h"

#include <algorithm>
#include <cstring>

#include "engine/render_context.h"
#include "engine/shade/pixel_factors.h"
#include "engine/trace/embree_scene.h"
#include "engine/trace/sample_cache.h"
#include "engine/trace/single_sample_pass.h"
#include "scene/memory_estimate.h"
#include "scene/validation.h"

namespace gloss {

namespace {
void copy_rows(const Image& band, int row0, Image& image) {
  std::memcpy(&image.pixels[static_cast<std::size_t>(row0) * image.width], band.pixels.data(),
              band.pixels.size() * sizeof(glm::vec3));
}
}  // namespace

TermImages render(const Scene& scene, const RenderOptions& options) {
  validate_scene(scene);
  const EmbreeScene embree(scene);
  RenderContext ctx;
  ctx.scene = &scene;
  ctx.embree = &embree;
  ctx.plan = make_render_plan(scene, options.full_plan);

  const int w = scene.render.width, h = scene.render.height, spp = scene.render.spp;
  // Larger images go band by band, each band's sample cache about kSampleBandBytes; validation
  // counted the same (scene/memory_estimate.h).
  const int band_rows = sample_band_rows(w, h, spp, ctx.plan.lights.size());

  TermImages out;
  out.total = Image(w, h);
  if (options.terms) {
    out.emissive = out.ambient = out.diffuse = out.specular = Image(w, h);
  }
  SampleCache cache;
  PixelFactors factors;
  TermImages band;
  for (int row0 = 0; row0 < h; row0 += band_rows) {
    cache = make_sample_cache(scene, w, h, spp, row0, std::min(band_rows, h - row0));
    if (spp == 1) {  // the same bits, one pass (with the total, unless terms are wanted)
      trace_single_sample(cache, ctx, factors, options.terms ? nullptr : &band.total);
    } else {
      add_samples(cache, ctx, spp);
      build_pixel_factors(cache, ctx, factors);
    }
    if (spp != 1 || options.terms) combine_terms(factors, ctx, band, options.terms);
    copy_rows(band.total, row0, out.total);
    if (options.terms) {
      copy_rows(band.emissive, row0, out.emissive);
      copy_rows(band.ambient, row0, out.ambient);
      copy_rows(band.diffuse, row0, out.diffuse);
      copy_rows(band.specular, row0, out.specular);
    }
  }
  return out;
}

}  // namespace gloss
