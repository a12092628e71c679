#include <cassert>
#include <type_traits>

#include <tbb/parallel_for.h>

#include "engine/parallel_loops.h"
#include "engine/shade/pixel_factors.h"
#include "engine/shade/recombination.h"
#include "shading/total.h"

// combine_terms (pixel_factors.h): the recombination of per-pixel factors with the scene's
// material constants and light colours, the path every constant edit takes.

namespace gloss {

void combine_terms(const PixelFactors& factors, const RenderContext& ctx, TermImages& out,
                   bool terms) {
  const int w = factors.width, h = factors.height;
  const std::size_t pixels = static_cast<std::size_t>(w) * h;
  const std::size_t lights = factors.lights;
  auto fit = [&](Image& image) {
    if (image.width != w || image.height != h) image = Image(w, h);
  };
  fit(out.total);
  if (terms) {
    fit(out.emissive);
    fit(out.ambient);
    fit(out.diffuse);
    fit(out.specular);
  }
  const Recombination recombination(ctx);
  // The factors were built for the same plan (an edit that changes it is classed `light`).
  assert(recombination.lights() == lights);
  // Where primary rays miss: the environment (its sky, when shown) or the background colour.
  const bool sky = recombination.sky_shown() && factors.sky.size() == pixels;
  auto pixel_total = [&](const glm::vec3 term[4], float missed, std::size_t i) {
    return sky ? recombination.total_under_sky(term, factors.sky[i])
               : recombination.total(term, missed);
  };
  // The pixel loop, instantiated per (one sample, term images) so it holds no such branches.
  auto pixels_loop = [&](auto single_tag, auto terms_tag, std::size_t begin, std::size_t end) {
    constexpr bool kSingle = decltype(single_tag)::value;  // weight, background from material
    constexpr bool kTerms = decltype(terms_tag)::value;
    for (std::size_t i = begin; i != end; ++i) {
      glm::vec3 term[4] = {glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(0.0f)};
      const std::int32_t m = factors.material[i];
      const float weight = kSingle ? 1.0f : factors.weight[i];
      const float missed = kSingle ? (m < 0 ? 1.0f : 0.0f) : factors.background[i];
      if (m >= 0) {
        recombination.terms(m, weight, factors.diffuse.data() + i, factors.specular.data() + i,
                            pixels, term);
      }
      out.total.pixels[i] = pixel_total(term, missed, i);
      if constexpr (kTerms) {
        out.emissive.pixels[i] = term[0];
        out.ambient.pixels[i] = term[1];
        out.diffuse.pixels[i] = term[2];
        out.specular.pixels[i] = term[3];
      }
    }
  };
  const bool single = factors.samples == 1;
  ForkJoinFence fence;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, pixels, 16384),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      const ForkJoinFence::Task task(fence);
                      DenormalsOff denormals_off;
                      const std::size_t b = range.begin(), e = range.end();
                      using T = std::true_type;
                      using F = std::false_type;
                      if (single && terms) pixels_loop(T{}, T{}, b, e);
                      if (single && !terms) pixels_loop(T{}, F{}, b, e);
                      if (!single && terms) pixels_loop(F{}, T{}, b, e);
                      if (!single && !terms) pixels_loop(F{}, F{}, b, e);
                    });
  fence.join();
  // Adaptive sampling's refined pixels: their weight and background share are their own.
  for (std::size_t k = 0; k < factors.refined_pixel.size(); ++k) {
    const std::size_t i = factors.refined_pixel[k];
    glm::vec3 term[4] = {glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(0.0f)};
    const std::int32_t m = factors.material[i];
    if (m >= 0) {
      recombination.terms(m, factors.refined_weight[k], factors.diffuse.data() + i,
                          factors.specular.data() + i, pixels, term);
    }
    out.total.pixels[i] = pixel_total(term, factors.refined_background[k], i);
    if (terms) {
      out.emissive.pixels[i] = term[0];
      out.ambient.pixels[i] = term[1];
      out.diffuse.pixels[i] = term[2];
      out.specular.pixels[i] = term[3];
    }
  }
  for (std::size_t e = 0; e < factors.extra_pixel.size(); ++e) {
    glm::vec3 term[4];
    recombination.terms(factors.extra_material[e], factors.extra_weight[e],
                        factors.extra_diffuse.data() + e * lights,
                        factors.extra_specular.data() + e * lights, 1, term);
    const std::size_t i = factors.extra_pixel[e];
    out.total.pixels[i] += form_total(term[0], term[1], term[2], term[3]);
    if (terms) {
      out.emissive.pixels[i] += term[0];
      out.ambient.pixels[i] += term[1];
      out.diffuse.pixels[i] += term[2];
      out.specular.pixels[i] += term[3];
    }
  }
}

}  // namespace gloss
