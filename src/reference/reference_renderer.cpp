#include "reference/reference_renderer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <type_traits>

#include <embree3/rtcore.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "engine/parallel_loops.h"
#include "engine/trace/embree_scene.h"
#include "engine/trace/self_shadow.h"
#include "physical/reference_brdf.h"
#include "reference/reference_sample.h"
#include "scene/camera.h"
#include "scene/fields/validation.h"
#include "shading/light_source.h"
#include "shading/sampling.h"
#include "shading/shading.h"
#include "shading/surface.h"
#include "shading/total.h"

namespace gloss {

namespace {

using namespace reference_detail;

// 1 for pixels whose own samples are mixed or that differ from one of their 8 neighbours.
void edge_mask(const std::vector<SampleKey>& first, const std::vector<std::uint8_t>& mixed, int w,
               int h, std::vector<std::uint8_t>& out) {
  out.assign(first.size(), 0);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      bool edge = mixed[i] != 0;
      for (int dy = -1; dy <= 1 && !edge; ++dy) {
        for (int dx = -1; dx <= 1 && !edge; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
          edge = discontinuous(first[i], first[static_cast<std::size_t>(ny) * w + nx]);
        }
      }
      out[i] = edge ? 1 : 0;
    }
  }
}

}  // namespace

template <class T>
TermImages render_reference(const Scene& scene, const ReferenceOptions& options) {
  validate_scene(scene);
  if (options.spp < 0 || options.spp > kMaxSpp) {
    throw std::invalid_argument("render_reference: spp out of range");
  }
  const EmbreeScene embree(scene);
  Job<T> job = make_job<T>(scene, embree.handle(), options.spp > 0 ? options.spp : scene.render.spp,
                           options.pow.value_or(scene.render.pow));
  job.gouraud = options.gouraud;
  const ReferenceEnvironment environment(scene, options.environment);
  job.environment = &environment;
  if (options.physical) {
    for (const Material& m : scene.materials) {
      job.physical.push_back(m.reference
                                 ? std::optional<ReferenceBrdf>(make_reference_brdf(*m.reference))
                                 : std::nullopt);
    }
  }

  const int w = job.width, h = job.height;
  const std::size_t pixels = static_cast<std::size_t>(w) * h;
  TermImages out;
  out.total = out.emissive = out.ambient = out.diffuse = out.specular = Image(w, h);
  std::vector<SampleKey> first(options.edges != nullptr ? pixels : 0);
  std::vector<std::uint8_t> mixed(first.size(), 0);
  if (options.refined != nullptr && options.refined->size() != pixels) {
    throw std::invalid_argument("render_reference: refined mask of the wrong size");
  }

  auto rows = [&](const tbb::blocked_range<int>& range) {
    for (int y = range.begin(); y != range.end(); ++y) {
      if (options.cancel != nullptr && options.cancel->load(std::memory_order_relaxed)) return;
      for (int x = 0; x < w; ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * w + x;
        const int count = options.refined != nullptr && (*options.refined)[i] == 0 ? 1 : job.spp;
        const T inv_spp = T(1) / T(count);
        PixelSums<T> sum;
        SampleKey key0, key;
        bool is_mixed = false;
        for (int s = 0; s < count; ++s) {
          shade_sample(job, x, y, s, count, sum, s == 0 ? key0 : key);
          if (s > 0 && !is_mixed) is_mixed = discontinuous(key0, key);
        }
        const Vec3<T> e = sum.emissive * inv_spp, a = sum.ambient * inv_spp,
                      d = sum.diffuse * inv_spp, sp = sum.specular * inv_spp;
        out.emissive.pixels[i] = glm::vec3(e);
        out.ambient.pixels[i] = glm::vec3(a);
        out.diffuse.pixels[i] = glm::vec3(d);
        out.specular.pixels[i] = glm::vec3(sp);
        out.total.pixels[i] =
            glm::vec3(form_total(e, a, d, sp, missed_background(job, sum, inv_spp)));
        if (!first.empty()) {
          first[i] = key0;
          mixed[i] = is_mixed ? 1 : 0;
        }
      }
    }
  };
  tbb::parallel_for(tbb::blocked_range<int>(0, h, 1), [&](const tbb::blocked_range<int>& range) {
    if constexpr (std::is_same_v<T, float>) {
      DenormalsOff denormals_off;  // float results below the normal range must not slow it down
      rows(range);
    } else {
      rows(range);
    }
  });
  if (options.edges != nullptr) edge_mask(first, mixed, w, h, *options.edges);
  return out;
}

template TermImages render_reference<float>(const Scene&, const ReferenceOptions&);
template TermImages render_reference<double>(const Scene&, const ReferenceOptions&);

}  // namespace gloss
