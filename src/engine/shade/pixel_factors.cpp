#include "engine/shade/pixel_factors.h"

#include <algorithm>

#include <tbb/parallel_for.h>

#include "engine/parallel_loops.h"
#include "engine/shade/power_lanes.h"
#include "engine/simd/lane_gather.h"
#include "engine/simd/lane_mask.h"

namespace gloss {

namespace {
// Running sums of one material inside one pixel.
struct Group {
  std::int32_t material;
  int count;
};

struct BandExtras {
  std::vector<std::uint32_t> pixel;
  std::vector<std::int32_t> material;
  std::vector<float> weight, diffuse, specular;
};

}  // namespace

std::size_t PixelFactors::bytes() const {
  return material.size() * sizeof(std::int32_t) + (weight.size() + background.size()) * 4 +
         (diffuse.size() + specular.size()) * 4 + extra_pixel.size() * 8 +
         (extra_weight.size() + extra_diffuse.size() + extra_specular.size()) * 4;
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
                         float* specular) {
  if (n == kLanes && all_lanes_negative(material)) {  // all missed (image borders)
    for (int i = 0; i < kLanes; ++i) diffuse[i] = specular[i] = 0.0f;
    return;
  }
  specular_lanes(exponents, material, cosine, spec_weight, specular, n, mode);
  auto lanes = [&](int count) {
    for (int i = 0; i < count; ++i) diffuse[i] = material[i] < 0 ? 0.0f : diffuse_weight[i];
  };
  if (n == kLanes) {
    lanes(kLanes);  // a constant count: straight vector code
  } else {
    lanes(n);
  }
}

bool build_pixel_factors(const SampleCache& cache, const RenderContext& ctx, PixelFactors& out) {
  const Scene& scene = *ctx.scene;
  const std::size_t pixels = cache.pixel_count();
  const std::size_t lights = ctx.plan.lights.size();
  const int n = cache.samples();
  size_pixel_factors(out, cache.width, cache.height, n, lights);
  const int rows = band_rows(cache.width);
  std::vector<BandExtras> extras(static_cast<std::size_t>((cache.height + rows - 1) / rows));
  const float inv_n = n > 0 ? 1.0f / static_cast<float>(n) : 0.0f;
  const ShadingModel model = scene.render.model;
  const PowMode pow_mode = scene.render.pow;
  const MaterialExponents exponents = material_exponents(scene);
  const std::vector<std::int32_t> materials = object_materials(scene);
  constexpr int kRun = kLanes;  // pixels of a row handled together

  // One sample: no grouping, the lane helpers the fused first pass uses, row by row.
  auto single = [&](std::size_t idx, int m) {
    const SamplePlane& plane = cache.planes[0];
    single_sample_coverage(materials, &plane.object[idx], m, &out.material[idx]);
    for (std::size_t li = 0; li < lights; ++li) {
      const LightFactorPlane& f = plane.lights[li];
      single_sample_light(exponents, pow_mode, &out.material[idx], &f.diffuse_weight[idx],
                          &f.spec_weight[idx], f.cosine(model) + idx, m,
                          &out.diffuse[li * pixels + idx], &out.specular[li * pixels + idx]);
    }
  };

  if (n == 1) {
    return parallel_rows(cache.width, cache.height, ctx.cancel, [&](int y0, int y1) {
      for (int y = y0; y < y1; ++y) {
        for (int x = 0; x < cache.width; x += kRun) {
          single(static_cast<std::size_t>(y) * cache.width + x, std::min(kRun, cache.width - x));
        }
      }
    });
  }
  const bool done = parallel_rows(cache.width, cache.height, ctx.cancel, [&](int y0, int y1) {
    const int x0 = 0, x1 = cache.width;
    BandExtras& band_extras = extras[static_cast<std::size_t>(y0 / rows)];
    band_extras = BandExtras{};
    std::vector<Group> groups;
    std::vector<float> sums;  // [group * 2 * lights + 2 * light + {0: diffuse, 1: specular}]
    // Per run of pixels: each sample's material and weighted c^alpha (lanes helpers).
    std::vector<std::int32_t> run_material(n > 1 ? static_cast<std::size_t>(n) * kRun : 0);
    std::vector<float> run_specular(run_material.size() * lights);
    for (int y = y0; y < y1; ++y) {
      for (int xs = x0; xs < x1; xs += kRun) {
        const int m = std::min(kRun, x1 - xs);
        const std::size_t idx0 = static_cast<std::size_t>(y) * cache.width + xs;
        for (int s = 0; s < n; ++s) {
          const SamplePlane& plane = cache.planes[static_cast<std::size_t>(s)];
          std::int32_t* mat = &run_material[static_cast<std::size_t>(s) * kRun];
          for (int i = 0; i < m; ++i) {
            const std::int32_t object = plane.object[idx0 + i];
            mat[i] = object < 0 ? -1 : scene.objects[static_cast<std::size_t>(object)].material;
          }
          for (std::size_t li = 0; li < lights; ++li) {
            const LightFactorPlane& f = plane.lights[li];
            float* spec = &run_specular[(s * lights + li) * kRun];
            alignas(64) float power[kRun];
            specular_power_lanes(exponents, mat, f.cosine(model) + idx0, power, m, pow_mode);
            for (int i = 0; i < m; ++i) spec[i] = f.spec_weight[idx0 + i] * power[i];
          }
        }
        for (int i = 0; i < m; ++i) {
          const std::size_t idx = idx0 + i;
          groups.clear();
          sums.clear();
          int misses = 0;
          for (int s = 0; s < n; ++s) {
            const std::int32_t material = run_material[static_cast<std::size_t>(s) * kRun + i];
            if (material < 0) {
              ++misses;
              continue;
            }
            std::size_t g = 0;
            while (g < groups.size() && groups[g].material != material) ++g;
            if (g == groups.size()) {
              groups.push_back({material, 0});
              sums.resize(sums.size() + 2 * lights, 0.0f);
            }
            ++groups[g].count;
            float* acc = sums.data() + g * 2 * lights;
            const SamplePlane& plane = cache.planes[static_cast<std::size_t>(s)];
            for (std::size_t li = 0; li < lights; ++li) {
              acc[2 * li] += plane.lights[li].diffuse_weight[idx];
              acc[2 * li + 1] += run_specular[(s * lights + li) * kRun + i];
            }
          }
          out.background[idx] = static_cast<float>(misses) * inv_n;
          out.material[idx] = groups.empty() ? -1 : groups[0].material;
          out.weight[idx] = groups.empty() ? 0.0f : static_cast<float>(groups[0].count) * inv_n;
          for (std::size_t li = 0; li < lights; ++li) {
            out.diffuse[li * pixels + idx] = groups.empty() ? 0.0f : sums[2 * li] * inv_n;
            out.specular[li * pixels + idx] = groups.empty() ? 0.0f : sums[2 * li + 1] * inv_n;
          }
          for (std::size_t g = 1; g < groups.size(); ++g) {
            band_extras.pixel.push_back(static_cast<std::uint32_t>(idx));
            band_extras.material.push_back(groups[g].material);
            band_extras.weight.push_back(static_cast<float>(groups[g].count) * inv_n);
            for (std::size_t li = 0; li < lights; ++li) {
              band_extras.diffuse.push_back(sums[g * 2 * lights + 2 * li] * inv_n);
              band_extras.specular.push_back(sums[g * 2 * lights + 2 * li + 1] * inv_n);
            }
          }
        }
      }
    }
  });
  if (!done) return false;
  for (const BandExtras& t : extras) {  // band order: deterministic whatever the thread count
    out.extra_pixel.insert(out.extra_pixel.end(), t.pixel.begin(), t.pixel.end());
    out.extra_material.insert(out.extra_material.end(), t.material.begin(), t.material.end());
    out.extra_weight.insert(out.extra_weight.end(), t.weight.begin(), t.weight.end());
    out.extra_diffuse.insert(out.extra_diffuse.end(), t.diffuse.begin(), t.diffuse.end());
    out.extra_specular.insert(out.extra_specular.end(), t.specular.begin(), t.specular.end());
  }
  return true;
}

}  // namespace gloss
