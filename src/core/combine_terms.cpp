#include <type_traits>

#include <tbb/parallel_for.h>

#include "parallel_tiles.h"
#include "pixel_factors.h"

// combine_terms (pixel_factors.h): the recombination of per-pixel factors with the scene's
// material constants and light colours, the path every constant edit takes.

namespace gloss {

namespace {

// Material constants folded with the light colours and the scene ambient, per material.
struct MaterialTerms {
  glm::vec3 emissive, ambient;   // ke, ka * (A_scene + sum La)
  std::vector<glm::vec3> kd_ld;  // kd * Ld_i, per planned light
  std::vector<glm::vec3> ks_ls;  // ks * Ls_i (* energy normalisation), per planned light
};

std::vector<MaterialTerms> fold_materials(const RenderContext& ctx) {
  const Scene& scene = *ctx.scene;
  glm::vec3 ambient_light = scene.ambient;
  for (const PointLight& light : scene.lights) ambient_light += light.ambient;
  std::vector<MaterialTerms> out(scene.materials.size());
  for (std::size_t m = 0; m < scene.materials.size(); ++m) {
    const Material& mat = scene.materials[m];
    MaterialTerms& t = out[m];
    t.emissive = mat.emission;
    t.ambient = mat.ambient * ambient_light;
    const float norm = scene.render.energy_normalize
                           ? energy_normalization(scene.render.model, mat.shininess)
                           : 1.0f;
    for (int index : ctx.plan.lights) {
      const PointLight& light = scene.lights[static_cast<std::size_t>(index)];
      t.kd_ld.push_back(mat.diffuse * light.diffuse);
      t.ks_ls.push_back(mat.specular * norm * light.specular);
    }
  }
  return out;
}

}  // namespace

void combine_terms(const PixelFactors& factors, const RenderContext& ctx, TermImages& out,
                   bool terms) {
  const std::vector<MaterialTerms> folded = fold_materials(ctx);
  const glm::vec3 background = ctx.scene->background;
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
  // The folded constants flat, per material: ke, ka (A + sum La), then per light kd Ld, ks Ls
  // (3 floats each): one pointer per pixel instead of nested vectors.
  const std::size_t stride = 6 + 6 * lights;
  std::vector<float> flat(folded.size() * stride);
  for (std::size_t m = 0; m < folded.size(); ++m) {
    float* f = &flat[m * stride];
    for (int c = 0; c < 3; ++c) {
      f[c] = folded[m].emissive[c];
      f[3 + c] = folded[m].ambient[c];
      for (std::size_t li = 0; li < lights; ++li) {
        f[6 + 6 * li + c] = folded[m].kd_ld[li][c];
        f[9 + 6 * li + c] = folded[m].ks_ls[li][c];
      }
    }
  }
  // One material's terms in one pixel, from its weight and per-light factor means (light li's
  // at diffuse[li * step], specular[li * step]).
  auto contribution = [&](std::int32_t material, float weight, const float* diffuse,
                          const float* specular, std::size_t step, glm::vec3 term[4]) {
    const float* f = &flat[static_cast<std::size_t>(material) * stride];
    term[0] = weight * glm::vec3(f[0], f[1], f[2]);
    term[1] = weight * glm::vec3(f[3], f[4], f[5]);
    term[2] = glm::vec3(0.0f);
    term[3] = glm::vec3(0.0f);
    for (std::size_t li = 0; li < lights; ++li) {
      const float* k = f + 6 + 6 * li;
      term[2] += glm::vec3(k[0], k[1], k[2]) * diffuse[li * step];
      term[3] += glm::vec3(k[3], k[4], k[5]) * specular[li * step];
    }
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
      if (m >= 0) contribution(m, weight, &factors.diffuse[i], &factors.specular[i], pixels, term);
      out.total.pixels[i] = term[0] + term[1] + term[2] + term[3] + missed * background;
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
  for (std::size_t e = 0; e < factors.extra_pixel.size(); ++e) {
    glm::vec3 term[4];
    contribution(factors.extra_material[e], factors.extra_weight[e],
                 &factors.extra_diffuse[e * lights], &factors.extra_specular[e * lights], 1, term);
    const std::size_t i = factors.extra_pixel[e];
    out.total.pixels[i] += term[0] + term[1] + term[2] + term[3];
    if (terms) {
      out.emissive.pixels[i] += term[0];
      out.ambient.pixels[i] += term[1];
      out.diffuse.pixels[i] += term[2];
      out.specular.pixels[i] += term[3];
    }
  }
}

}  // namespace gloss
