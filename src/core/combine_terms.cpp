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
  const bool single = factors.samples == 1;  // weight and background implied by material
  // One material's contribution to one pixel, from its weight and per-light factor means.
  auto contribution = [&](std::int32_t material, float weight, const float* diffuse,
                          const float* specular, std::size_t stride, glm::vec3 term[4]) {
    const MaterialTerms& mt = folded[static_cast<std::size_t>(material)];
    term[0] = weight * mt.emissive;
    term[1] = weight * mt.ambient;
    term[2] = glm::vec3(0.0f);
    term[3] = glm::vec3(0.0f);
    for (std::size_t li = 0; li < lights; ++li) {
      term[2] += mt.kd_ld[li] * diffuse[li * stride];
      term[3] += mt.ks_ls[li] * specular[li * stride];
    }
  };
  ForkJoinFence fence;
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, pixels, 16384),
      [&](const tbb::blocked_range<std::size_t>& range) {
        const ForkJoinFence::Task task(fence);
        DenormalsOff denormals_off;
        for (std::size_t i = range.begin(); i != range.end(); ++i) {
          glm::vec3 term[4] = {glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(0.0f)};
          const std::int32_t m = factors.material[i];
          const float weight = single ? 1.0f : factors.weight[i];
          const float missed = single ? (m < 0 ? 1.0f : 0.0f) : factors.background[i];
          if (m >= 0) {
            contribution(m, weight, &factors.diffuse[i], &factors.specular[i], pixels, term);
          }
          out.total.pixels[i] = term[0] + term[1] + term[2] + term[3] + missed * background;
          if (terms) {
            out.emissive.pixels[i] = term[0];
            out.ambient.pixels[i] = term[1];
            out.diffuse.pixels[i] = term[2];
            out.specular.pixels[i] = term[3];
          }
        }
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
