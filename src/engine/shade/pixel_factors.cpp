#include "engine/shade/pixel_factors.h"

#include "engine/shade/pixel_groups.h"
#include "engine/shade/textured_factors.h"

#include <algorithm>

#include <tbb/parallel_for.h>

#include "engine/parallel_loops.h"
#include "engine/shade/power_lanes.h"
#include "engine/simd/lane_gather.h"
#include "engine/simd/lane_mask.h"

namespace gloss {

void FactorExtras::append_to(PixelFactors& out) const {
  out.extra_pixel.insert(out.extra_pixel.end(), pixel.begin(), pixel.end());
  out.extra_material.insert(out.extra_material.end(), material.begin(), material.end());
  out.extra_weight.insert(out.extra_weight.end(), weight.begin(), weight.end());
  out.extra_diffuse.insert(out.extra_diffuse.end(), diffuse.begin(), diffuse.end());
  out.extra_specular.insert(out.extra_specular.end(), specular.begin(), specular.end());
  out.extra_textured.insert(out.extra_textured.end(), textured.begin(), textured.end());
}

void PixelGroups::write(std::size_t idx, float inv_n, PixelFactors& out, float& weight,
                        float& background, FactorExtras& extras, float* record) const {
  const std::size_t pixels = out.material.size();
  const bool none = m_groups.empty();
  background = static_cast<float>(m_misses) * inv_n;
  out.material[idx] = none ? -1 : m_groups[0].material;
  weight = none ? 0.0f : static_cast<float>(m_groups[0].count) * inv_n;
  for (std::size_t li = 0; li < m_lights; ++li) {
    out.diffuse[li * pixels + idx] = none ? 0.0f : m_sums[2 * li] * inv_n;
    out.specular[li * pixels + idx] = none ? 0.0f : m_sums[2 * li + 1] * inv_n;
  }
  if (record != nullptr) {
    for (std::size_t j = 0; j < m_textured; ++j) record[j] = none ? 0.0f : m_records[j] * inv_n;
  }
  for (std::size_t g = 1; g < m_groups.size(); ++g) {
    extras.pixel.push_back(static_cast<std::uint32_t>(idx));
    extras.material.push_back(m_groups[g].material);
    extras.weight.push_back(static_cast<float>(m_groups[g].count) * inv_n);
    for (std::size_t li = 0; li < m_lights; ++li) {
      extras.diffuse.push_back(m_sums[g * 2 * m_lights + 2 * li] * inv_n);
      extras.specular.push_back(m_sums[g * 2 * m_lights + 2 * li + 1] * inv_n);
    }
    for (std::size_t j = 0; j < m_textured; ++j) {
      extras.textured.push_back(m_records[g * m_textured + j] * inv_n);
    }
  }
}

std::size_t PixelFactors::bytes() const {
  return material.size() * sizeof(std::int32_t) + (weight.size() + background.size()) * 4 +
         (textured.size() + refined_textured.size() + extra_textured.size()) * 4 +
         refined_pixel.size() * 12 + (diffuse.size() + specular.size()) * 4 +
         extra_pixel.size() * 8 +
         (extra_weight.size() + extra_diffuse.size() + extra_specular.size()) * 4 +
         sky.size() * sizeof(glm::vec3);
}

void size_pixel_factors(PixelFactors& out, int width, int height, int samples, std::size_t lights) {
  const std::size_t pixels = static_cast<std::size_t>(width) * height;
  out.width = width;
  out.height = height;
  out.samples = samples;
  out.lights = lights;
  out.material.resize(pixels);
  out.weight.resize(samples != 1 ? pixels : 0);
  out.background.resize(samples != 1 ? pixels : 0);
  out.diffuse.resize(pixels * lights);
  out.specular.resize(pixels * lights);
  out.extra_pixel.clear();
  out.extra_material.clear();
  out.extra_weight.clear();
  out.extra_diffuse.clear();
  out.extra_specular.clear();
  out.refined_pixel.clear();
  out.refined_weight.clear();
  out.refined_background.clear();
  out.extra_textured.clear();
  out.refined_textured.clear();
  out.textured.clear();
  out.textured_stride = 0;
  out.texel_channels = 0;
  out.texel.fill(nullptr);
}

std::vector<std::int32_t> object_materials(const Scene& scene) {
  std::vector<std::int32_t> out;
  for (const Object& object : scene.objects) out.push_back(object.material);
  if (out.empty()) out.push_back(-1);  // missed lanes gather entry 0
  return out;
}

void single_sample_coverage(const std::vector<std::int32_t>& object_material,
                            const std::int32_t* object, int n, std::int32_t* material) {
  if (n == kLanes) {                   // fixed-count loops: straight vector code
    if (all_lanes_negative(object)) {  // all missed (image borders)
      for (int i = 0; i < kLanes; ++i) material[i] = -1;
      return;
    }
    alignas(64) std::int32_t index[kLanes];
    for (int i = 0; i < kLanes; ++i) index[i] = std::max(object[i], 0);
    gather16(object_material.data(), object_material.size(), index, material);
    for (int i = 0; i < kLanes; ++i) material[i] = object[i] < 0 ? -1 : material[i];
    return;
  }
  for (int i = 0; i < n; ++i) {
    material[i] = object[i] < 0 ? -1 : object_material[static_cast<std::size_t>(object[i])];
  }
}

void single_sample_light(const MaterialExponents& exponents, PowMode mode,
                         const std::int32_t* material, const float* diffuse_weight,
                         const float* spec_weight, const float* cosine, int n, float* diffuse,
                         float* specular, const ScaledExponent* scaled) {
  if (n == kLanes && all_lanes_negative(material)) {  // all missed (image borders)
    for (int i = 0; i < kLanes; ++i) diffuse[i] = specular[i] = 0.0f;
    return;
  }
  specular_lanes(exponents, material, cosine, spec_weight, specular, n, mode, scaled);
  auto lanes = [&](int count) {
    for (int i = 0; i < count; ++i) diffuse[i] = material[i] < 0 ? 0.0f : diffuse_weight[i];
  };
  if (n == kLanes) {
    lanes(kLanes);  // a constant count: straight vector code
  } else {
    lanes(n);
  }
}

bool build_centre_factors(const SampleCache& cache, const RenderContext& ctx, PixelFactors& out) {
  const std::size_t pixels = cache.pixel_count();
  const std::size_t lights = ctx.plan.slots();
  size_pixel_factors(out, cache.width, cache.height, 1, lights);
  const ShadingModel model = ctx.scene->render.model;
  const PowMode pow_mode = ctx.scene->render.pow;
  const MaterialExponents exponents = material_exponents(*ctx.scene);
  const std::vector<std::int32_t> materials = object_materials(*ctx.scene);
  const SamplePlane& plane = cache.planes.at(0);
  const int alpha_channel = ctx.plan.textures.alpha_channel();
  borrow_texels(plane, ctx.plan, out);  // one sample: the texel channels multiply the terms
  // No grouping: the lane helpers the fused first pass uses, a run of kLanes pixels at a time.
  return parallel_rows(cache.width, cache.height, ctx.cancel, [&](int y0, int y1) {
    for (int y = y0; y < y1; ++y) {
      for (int x = 0; x < cache.width; x += kLanes) {
        const std::size_t idx = static_cast<std::size_t>(y) * cache.width + x;
        const int m = std::min(kLanes, cache.width - x);
        single_sample_coverage(materials, &plane.object[idx], m, &out.material[idx]);
        ScaledExponent storage;  // once for every light of the run
        const ScaledExponent* scaled = scaled_exponents(
            ctx, exponents, &out.material[idx],
            alpha_channel >= 0 ? plane.texels[alpha_channel].data() + idx : nullptr, m, storage);
        for (std::size_t li = 0; li < lights; ++li) {
          const LightFactorPlane& f = plane.lights[li];
          single_sample_light(exponents, pow_mode, &out.material[idx], &f.diffuse_weight[idx],
                              &f.spec_weight[idx], f.cosine(model, idx), m,
                              &out.diffuse[li * pixels + idx], &out.specular[li * pixels + idx],
                              scaled);
        }
      }
    }
  });
}

bool build_pixel_factors(const SampleCache& cache, const RenderContext& ctx, PixelFactors& out) {
  const int n = cache.samples();
  if (n == 1) {  // adaptive sampling: the centres as one sample, then the refined pixels
    return build_centre_factors(cache, ctx, out) && refine_pixel_factors(cache, ctx, out);
  }
  const Scene& scene = *ctx.scene;
  const std::size_t pixels = cache.pixel_count();
  const std::size_t lights = ctx.plan.slots();
  size_pixel_factors(out, cache.width, cache.height, n, lights);
  const int rows = band_rows(cache.width);
  std::vector<FactorExtras> extras(static_cast<std::size_t>((cache.height + rows - 1) / rows));
  const float inv_n = n > 0 ? 1.0f / static_cast<float>(n) : 0.0f;
  const ShadingModel model = scene.render.model;
  const PowMode pow_mode = scene.render.pow;
  const MaterialExponents exponents = material_exponents(scene);
  constexpr int kRun = kLanes;  // pixels of a row handled together

  const int alpha_channel = ctx.plan.textures.alpha_channel();
  const bool textured = has_colour_texels(ctx.plan.textures);
  if (textured) {
    out.textured_stride = textured_stride(lights);
    out.textured.resize(pixels * out.textured_stride);
  }
  const bool done = parallel_rows(cache.width, cache.height, ctx.cancel, [&](int y0, int y1) {
    FactorExtras& band_extras = extras[static_cast<std::size_t>(y0 / rows)];
    band_extras = FactorExtras{};
    PixelGroups groups(lights, out.textured_stride);
    std::vector<float> texel(kMaxTexelChannels), diffuse(lights), specular(lights);
    // Per run of pixels: each sample's material and weighted c^alpha (lanes helpers).
    std::vector<std::int32_t> run_material(static_cast<std::size_t>(n) * kRun);
    std::vector<float> run_specular(run_material.size() * lights);
    for (int y = y0; y < y1; ++y) {
      for (int xs = 0; xs < cache.width; xs += kRun) {
        const int m = std::min(kRun, cache.width - xs);
        const std::size_t idx0 = static_cast<std::size_t>(y) * cache.width + xs;
        for (int s = 0; s < n; ++s) {
          const SamplePlane& plane = cache.planes[static_cast<std::size_t>(s)];
          std::int32_t* mat = &run_material[static_cast<std::size_t>(s) * kRun];
          for (int i = 0; i < m; ++i) {
            const std::int32_t object = plane.object[idx0 + i];
            mat[i] = object < 0 ? -1 : scene.objects[static_cast<std::size_t>(object)].material;
          }
          ScaledExponent storage;  // once for every light of the sample's run
          const ScaledExponent* scaled = scaled_exponents(
              ctx, exponents, mat,
              alpha_channel >= 0 ? plane.texels[alpha_channel].data() + idx0 : nullptr, m, storage);
          for (std::size_t li = 0; li < lights; ++li) {
            const LightFactorPlane& f = plane.lights[li];
            float* spec = &run_specular[(s * lights + li) * kRun];
            alignas(64) float power[kRun];
            if (scaled != nullptr) {
              scaled_power_lanes(exponents, mat, f.cosine(model, idx0), power, m, pow_mode,
                                 *scaled);
            } else {
              specular_power_lanes(exponents, mat, f.cosine(model, idx0), power, m, pow_mode);
            }
            for (int i = 0; i < m; ++i) spec[i] = f.spec_weight[idx0 + i] * power[i];
          }
        }
        for (int i = 0; i < m; ++i) {
          const std::size_t idx = idx0 + i;
          groups.clear();
          for (int s = 0; s < n; ++s) {
            float* record = nullptr;
            float* acc = groups.add(run_material[static_cast<std::size_t>(s) * kRun + i],
                                    textured ? &record : nullptr);
            if (acc == nullptr) continue;
            const SamplePlane& plane = cache.planes[static_cast<std::size_t>(s)];
            for (std::size_t li = 0; li < lights; ++li) {
              acc[2 * li] += plane.lights[li].diffuse_weight[idx];
              acc[2 * li + 1] += run_specular[(s * lights + li) * kRun + i];
            }
            if (textured) {
              sample_texels(plane, idx, texel.data(), diffuse.data());
              for (std::size_t li = 0; li < lights; ++li) {
                specular[li] = run_specular[(s * lights + li) * kRun + i];
              }
              add_textured_sample(ctx.plan.textures, texel.data(), lights, diffuse.data(),
                                  specular.data(), record);
            }
          }
          groups.write(idx, inv_n, out, out.weight[idx], out.background[idx], band_extras,
                       textured ? &out.textured[idx * out.textured_stride] : nullptr);
        }
      }
    }
  });
  if (!done) return false;
  for (const FactorExtras& t : extras) t.append_to(out);
  return true;
}

}  // namespace gloss
