#include <cassert>
#include <cstring>
#include <type_traits>

#include <tbb/parallel_for.h>

#include "engine/parallel_loops.h"
#include "engine/shade/pixel_factors.h"
#include "engine/shade/recombination.h"
#include "shading/total.h"

// combine_terms (pixel_factors.h): the recombination of per-pixel factors with the scene's
// material constants and light colours, the path every constant edit takes; and
// combine_over_centres, the same total for the adaptive pass from the centre image it refines.

namespace gloss {

namespace {
// Where primary rays miss: the environment's sky (when shown and made for this image) or the
// background colour.
bool shows_sky(const PixelFactors& factors, const Recombination& recombination) {
  const std::size_t pixels = static_cast<std::size_t>(factors.width) * factors.height;
  return recombination.sky_shown() && factors.sky.size() == pixels;
}

// The pixels combine_terms' dense loop does not finish, into total (and the four term images of
// out when given): adaptive sampling's refined pixels (their weight and background share are
// their own; written whole) and the further materials of mixed pixels (added). With maps, each
// has a textured record (textured_factors.h) in place of its scalar factors.
void recombine_refined(const PixelFactors& factors, const Recombination& recombination,
                       Image& total, TermImages* terms) {
  const std::size_t pixels = static_cast<std::size_t>(factors.width) * factors.height;
  const std::size_t lights = factors.lights;
  const bool sky = shows_sky(factors, recombination);
  const bool records = factors.textured_stride > 0;
  for (std::size_t k = 0; k < factors.refined_pixel.size(); ++k) {
    const std::size_t i = factors.refined_pixel[k];
    glm::vec3 term[4] = {glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(0.0f)};
    const std::int32_t m = factors.material[i];
    if (m >= 0 && records) {
      recombination.textured_terms(m, &factors.refined_textured[k * factors.textured_stride], term);
    } else if (m >= 0) {
      recombination.terms(m, factors.refined_weight[k], factors.diffuse.data() + i,
                          factors.specular.data() + i, pixels, term);
    }
    total.pixels[i] = sky ? recombination.total_under_sky(term, factors.sky[i])
                          : recombination.total(term, factors.refined_background[k]);
    if (terms != nullptr) {
      terms->emissive.pixels[i] = term[0];
      terms->ambient.pixels[i] = term[1];
      terms->diffuse.pixels[i] = term[2];
      terms->specular.pixels[i] = term[3];
    }
  }
  for (std::size_t e = 0; e < factors.extra_pixel.size(); ++e) {
    glm::vec3 term[4];
    if (records) {
      recombination.textured_terms(factors.extra_material[e],
                                   &factors.extra_textured[e * factors.textured_stride], term);
    } else {
      recombination.terms(factors.extra_material[e], factors.extra_weight[e],
                          factors.extra_diffuse.data() + e * lights,
                          factors.extra_specular.data() + e * lights, 1, term);
    }
    const std::size_t i = factors.extra_pixel[e];
    total.pixels[i] += form_total(term[0], term[1], term[2], term[3]);
    if (terms != nullptr) {
      terms->emissive.pixels[i] += term[0];
      terms->ambient.pixels[i] += term[1];
      terms->diffuse.pixels[i] += term[2];
      terms->specular.pixels[i] += term[3];
    }
  }
}
}  // namespace

void combine_terms(const PixelFactors& factors, const RenderContext& ctx, TermImages& out,
                   bool terms) {
  const int w = factors.width, h = factors.height;
  const std::size_t pixels = static_cast<std::size_t>(w) * h;
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
  assert(recombination.lights() == factors.lights);
  const bool sky = shows_sky(factors, recombination);
  // Maps (textured_factors.h): with one sample the texel channels multiply the terms, with
  // more each pixel's textured record replaces its scalar factors.
  const TexturePlan& maps = ctx.plan.textures;
  const int channel[4] = {maps.ke_channel(), maps.ka_channel(), maps.kd_channel(),
                          maps.ks_channel()};
  // The channels' arrays looked up once, not per pixel (null: the term has no map).
  const float* texel[4][3] = {};
  for (int t = 0; t < 4 && factors.texel_channels > 0; ++t) {
    for (int c = 0; c < 3 && channel[t] >= 0; ++c) {
      texel[t][c] = factors.texel[static_cast<std::size_t>(channel[t] + c)];
    }
  }
  // The pixel loop, instantiated per (one sample, term images, maps) so it holds no such
  // branches. kMaps: 0 none, 1 texel channels (one sample), 2 textured records.
  auto pixels_loop = [&](auto single_tag, auto terms_tag, auto maps_tag, std::size_t begin,
                         std::size_t end) {
    constexpr bool kSingle = decltype(single_tag)::value;  // weight, background from material
    constexpr bool kTerms = decltype(terms_tag)::value;
    constexpr int kMaps = decltype(maps_tag)::value;
    // Locals, not the captured arrays: the stores to the images may alias any float, and GCC
    // otherwise reloads every pointer per pixel.
    const float* tx[4][3];
    for (int t = 0; t < 4; ++t) {
      for (int c = 0; c < 3; ++c) tx[t][c] = texel[t][c];
    }
    const std::int32_t* const material = factors.material.data();
    const float* const diffuse = factors.diffuse.data();
    const float* const specular = factors.specular.data();
    glm::vec3* const total = out.total.pixels.data();
    for (std::size_t i = begin; i != end; ++i) {
      glm::vec3 term[4] = {glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(0.0f)};
      const std::int32_t m = material[i];
      const float weight = kSingle ? 1.0f : factors.weight[i];
      const float missed = kSingle ? (m < 0 ? 1.0f : 0.0f) : factors.background[i];
      if (m >= 0) {
        if constexpr (kMaps == 2) {
          recombination.textured_terms(m, &factors.textured[i * factors.textured_stride], term);
        } else {
          recombination.terms(m, weight, diffuse + i, specular + i, pixels, term);
          if constexpr (kMaps == 1) {
            for (int t = 0; t < 4; ++t) {
              if (tx[t][0] != nullptr) term[t] *= glm::vec3(tx[t][0][i], tx[t][1][i], tx[t][2][i]);
            }
          }
        }
      }
      total[i] = sky ? recombination.total_under_sky(term, factors.sky[i])
                     : recombination.total(term, missed);
      if constexpr (kTerms) {
        out.emissive.pixels[i] = term[0];
        out.ambient.pixels[i] = term[1];
        out.diffuse.pixels[i] = term[2];
        out.specular.pixels[i] = term[3];
      }
    }
  };
  const bool single = factors.samples == 1;
  const int map_kind = single ? (factors.texel_channels > 0 ? 1 : 0)
                              : (factors.textured_stride > 0 && !factors.textured.empty() ? 2 : 0);
  ForkJoinFence fence;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, pixels, 16384),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      const ForkJoinFence::Task task(fence);
                      DenormalsOff denormals_off;
                      const std::size_t b = range.begin(), e = range.end();
                      using T = std::true_type;
                      using F = std::false_type;
                      using M0 = std::integral_constant<int, 0>;
                      using M1 = std::integral_constant<int, 1>;
                      using M2 = std::integral_constant<int, 2>;
                      if (map_kind == 0) {
                        if (single && terms) pixels_loop(T{}, T{}, M0{}, b, e);
                        if (single && !terms) pixels_loop(T{}, F{}, M0{}, b, e);
                        if (!single && terms) pixels_loop(F{}, T{}, M0{}, b, e);
                        if (!single && !terms) pixels_loop(F{}, F{}, M0{}, b, e);
                      } else if (map_kind == 1) {
                        if (terms) pixels_loop(T{}, T{}, M1{}, b, e);
                        if (!terms) pixels_loop(T{}, F{}, M1{}, b, e);
                      } else {
                        if (terms) pixels_loop(F{}, T{}, M2{}, b, e);
                        if (!terms) pixels_loop(F{}, F{}, M2{}, b, e);
                      }
                    });
  fence.join();
  recombine_refined(factors, recombination, out.total, terms ? &out : nullptr);
}

void combine_over_centres(const PixelFactors& factors, const RenderContext& ctx,
                          const Image& centres, Image& total) {
  const std::size_t pixels = static_cast<std::size_t>(factors.width) * factors.height;
  assert(centres.width == factors.width && centres.height == factors.height);
  if (total.width != factors.width || total.height != factors.height) {
    total = Image(factors.width, factors.height);
  }
  // The copy in parallel blocks: one thread does not reach the memory bandwidth of two.
  ForkJoinFence fence;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, pixels, 65536),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      const ForkJoinFence::Task task(fence);
                      std::memcpy(&total.pixels[range.begin()], &centres.pixels[range.begin()],
                                  (range.end() - range.begin()) * sizeof(glm::vec3));
                    });
  fence.join();
  recombine_refined(factors, Recombination(ctx), total, nullptr);
}

}  // namespace gloss
