#include "engine/environment/prefiltered_environment.h"

#include <algorithm>
#include <cmath>
#include <mutex>

#include <tbb/parallel_for.h>

#include "shading/environment.h"

// libmvec's vector expf and logf (the powers of the lobe's weights), as power_lanes.cpp declares
// powf: <math.h> declares the SIMD variants only under -ffast-math.
extern "C" __attribute__((__simd__("notinbranch"))) float expf(float) noexcept;
extern "C" __attribute__((__simd__("notinbranch"))) float logf(float) noexcept;

namespace gloss {

namespace {

constexpr double kPi = 3.14159265358979323846;
// The lobe's weight is cut where it falls below this share of its peak: the cut loses at most
// about that share of the lobe's integral, far below the path's other errors.
constexpr double kLobeCut = 1e-4;
// The map levels a lobe is computed from are at most this coarse (radians per texel at the
// equator), however wide the lobe: the convolution's sums then stay within ~1e-3 of the
// integrals for the widest lobes (alpha 0 and 1).
constexpr double kMaxInputTexel = 0.05;

// One map level as the convolution reads it: per texel its radiance times its solid angle, its
// direction in sines and cosines of its row and column.
struct InputLevel {
  int width = 0, height = 0;
  std::vector<glm::vec3> radiance_omega;  // L times the texel's solid angle
  std::vector<float> row_cos, row_sin, row_omega, col_cos, col_sin;
};

// Solid angle of a texel of row j of an equirectangular W x H map.
double texel_omega(int j, int width, int height) {
  return (std::cos(kPi * j / height) - std::cos(kPi * (j + 1) / height)) * 2.0 * kPi / width;
}

InputLevel make_input(const Image& map) {
  InputLevel level;
  level.width = map.width;
  level.height = map.height;
  level.radiance_omega.resize(map.pixels.size());
  for (int j = 0; j < map.height; ++j) {
    const double omega = texel_omega(j, map.width, map.height);
    const double theta = kPi * (j + 0.5) / map.height;
    level.row_cos.push_back(static_cast<float>(std::cos(theta)));
    level.row_sin.push_back(static_cast<float>(std::sin(theta)));
    level.row_omega.push_back(static_cast<float>(omega));
    for (int i = 0; i < map.width; ++i) {
      level.radiance_omega[static_cast<std::size_t>(j) * map.width + i] =
          map.at(i, j) * static_cast<float>(omega);
    }
  }
  for (int i = 0; i < map.width; ++i) {
    const double phi = 2.0 * kPi * ((i + 0.5) / map.width - 0.5);
    level.col_cos.push_back(static_cast<float>(std::cos(phi)));
    level.col_sin.push_back(static_cast<float>(std::sin(phi)));
  }
  return level;
}

// Half the size: each texel the solid-angle-weighted mean of its four (the integral of L over
// it is kept exactly). Only for even sizes.
Image halve(const Image& map) {
  Image out(map.width / 2, map.height / 2);
  for (int j = 0; j < out.height; ++j) {
    const double w0 = texel_omega(2 * j, map.width, map.height);
    const double w1 = texel_omega(2 * j + 1, map.width, map.height);
    for (int i = 0; i < out.width; ++i) {
      const glm::dvec3 sum =
          glm::dvec3(map.at(2 * i, 2 * j) + map.at(2 * i + 1, 2 * j)) * w0 +
          glm::dvec3(map.at(2 * i, 2 * j + 1) + map.at(2 * i + 1, 2 * j + 1)) * w1;
      out.at(i, j) = glm::vec3(sum / (2.0 * (w0 + w1)));
    }
  }
  return out;
}

// The lobe's weights cos^alpha (0 where cos <= 0) of the cosines in place. Vector code:
// libmvec's expf and logf.
void lobe_weights(float* cosine, int n, float alpha) {
  if (alpha == 0.0f) {
#pragma omp simd
    for (int k = 0; k < n; ++k) cosine[k] = cosine[k] > 0.0f ? 1.0f : 0.0f;
    return;
  }
#pragma omp simd
  for (int k = 0; k < n; ++k) {
    // log of a positive number at most 1 on every lane (the others are dropped).
    const float base = cosine[k] > 0.0f ? std::min(cosine[k], 1.0f) : 1.0f;
    cosine[k] = cosine[k] > 0.0f ? expf(alpha * logf(base)) : 0.0f;
  }
}

// One prefiltered level: exponent alpha, out_w x out_h texels, from input, whose width must be a
// multiple s of out_w. Output column i then sits at the same place among the input columns
// around s i + s / 2 as every other, so for one output row and one input row the lobe's weights
// over the nearby input columns are one kernel for all the row's outputs: the powers are made
// once per pair of rows, and each output is a short sum of products (vector code).
Image convolve(const InputLevel& in, float alpha, int out_w, int out_h) {
  Image out(out_w, out_h);
  const int s = in.width / out_w;
  // The lobe's reach: c = cos(angle) >= c_min keeps every weight above kLobeCut of the peak.
  const double c_min = alpha < 1.0f ? 0.0 : std::pow(kLobeCut, 1.0 / alpha);
  const double reach = std::acos(c_min);
  // Output column i's centre is half a column to the left of input column s i + s / 2's centre
  // when s is even, on it when s is odd.
  const double shift = s % 2 == 0 ? -0.5 : 0.0;
  tbb::parallel_for(0, out_h, [&](int j) {
    const double theta_r = kPi * (j + 0.5) / out_h;
    const double cos_r = std::cos(theta_r), sin_r = std::sin(theta_r);
    const int row0 = std::max(0, static_cast<int>(std::floor((theta_r - reach) / kPi * in.height)));
    const int row1 =
        std::min(in.height - 1, static_cast<int>(std::floor((theta_r + reach) / kPi * in.height)));
    std::vector<double> sum_w(static_cast<std::size_t>(out_w), 0.0);
    std::vector<glm::dvec3> sum_l(static_cast<std::size_t>(out_w), glm::dvec3(0.0));
    std::vector<float> kernel, red, green, blue;
    for (int jj = row0; jj <= row1; ++jj) {
      const double a = cos_r * in.row_cos[jj], b = sin_r * in.row_sin[jj];
      // Half-width of the columns with a + b cos(dphi) >= c_min (plus one each side), or the
      // whole row.
      int half = in.width / 2;
      if (b > 1e-9) {
        const double x = (c_min - a) / b;
        if (x > 1.0) continue;  // the row is outside the lobe's reach
        if (x > -1.0) {
          half = std::min(half,
                          static_cast<int>(std::ceil(std::acos(x) / (2.0 * kPi) * in.width)) + 1);
        }
      } else if (a < c_min) {
        continue;
      }
      const int taps = 2 * half + 1;
      kernel.resize(static_cast<std::size_t>(taps));
      for (int d = -half; d <= half; ++d) {
        const double dphi = 2.0 * kPi * (d + shift) / in.width;
        kernel[static_cast<std::size_t>(d + half)] = static_cast<float>(a + b * std::cos(dphi));
      }
      lobe_weights(kernel.data(), taps, alpha);
      float weight = 0.0f;
      for (float k : kernel) weight += k;
      // The row with `half` columns wrapped on each side, so each output's taps are contiguous.
      const glm::vec3* row = in.radiance_omega.data() + static_cast<std::size_t>(jj) * in.width;
      // By channel (contiguous loads in the sums below).
      const std::size_t padded = static_cast<std::size_t>(in.width + 2 * half);
      red.resize(padded);
      green.resize(padded);
      blue.resize(padded);
      for (std::size_t c = 0; c < padded; ++c) {
        const glm::vec3& l = row[((static_cast<int>(c) - half) % in.width + in.width) % in.width];
        red[c] = l.x;
        green[c] = l.y;
        blue[c] = l.z;
      }
      const float omega = in.row_omega[jj];
      const float* k = kernel.data();
      for (int i = 0; i < out_w; ++i) {
        const std::size_t at = static_cast<std::size_t>(s * i + s / 2);  // s i + s / 2 - half
        const float *r = red.data() + at, *g = green.data() + at, *bl = blue.data() + at;
        float lr = 0.0f, lg = 0.0f, lb = 0.0f;
#pragma omp simd reduction(+ : lr, lg, lb)
        for (int d = 0; d < taps; ++d) {
          lr += k[d] * r[d];
          lg += k[d] * g[d];
          lb += k[d] * bl[d];
        }
        sum_w[static_cast<std::size_t>(i)] += double(weight) * omega;
        sum_l[static_cast<std::size_t>(i)] += glm::dvec3(lr, lg, lb);
      }
    }
    for (int i = 0; i < out_w; ++i) {
      const double w = sum_w[static_cast<std::size_t>(i)];
      out.at(i, j) = w > 0.0 ? glm::vec3(sum_l[static_cast<std::size_t>(i)] / w) : glm::vec3(0.0f);
    }
  });
  return out;
}

// The width of an output level nearest `wanted` (by ratio) that divides the input's width.
int dividing_width(int in_w, int wanted) {
  int best = in_w;
  double best_error = INFINITY;
  for (int s = 1; s <= in_w; ++s) {
    if (in_w % s != 0) continue;
    const double error = std::abs(std::log(double(in_w / s) / wanted));
    if (error < best_error) best = in_w / s, best_error = error;
  }
  return best;
}

}  // namespace

PrefilteredEnvironment::PrefilteredEnvironment(std::shared_ptr<const EnvironmentMap> map,
                                               const PrefilterSettings& settings)
    : m_map(std::move(map)), m_settings(settings) {
  const Image& source = m_map->radiance;
  // The map's pyramid, while the sizes halve evenly.
  std::vector<Image> pyramid;
  std::vector<InputLevel> inputs;
  inputs.push_back(make_input(source));
  for (const Image* level = &source;
       level->width % 2 == 0 && level->height % 2 == 0 && level->width >= 8;) {
    pyramid.push_back(halve(*level));
    level = &pyramid.back();
    inputs.push_back(make_input(*level));
  }
  const double res = std::max(1, settings.texels_per_lobe);
  m_exponents.push_back(0.0f);
  for (float alpha = 1.0f; alpha <= kTopPrefilteredExponent; alpha *= 2.0f) {
    m_exponents.push_back(alpha);
  }
  for (float alpha : m_exponents) {
    const double width = 1.0 / std::sqrt(std::max(alpha, 1.0f));  // the lobe's, radians
    // The coarsest input with texels no wider than width / res (and kMaxInputTexel).
    const double wanted = std::min(width / res, kMaxInputTexel);
    std::size_t k = 0;
    while (k + 1 < inputs.size() && 2.0 * kPi / inputs[k + 1].width <= wanted) ++k;
    const int least = alpha <= 1.0f ? 128 : 64;
    const int fine = static_cast<int>(std::ceil(2.0 * kPi * res / width));
    const int out_w = dividing_width(inputs[k].width, std::clamp(fine, least, source.width));
    const int out_h = std::max(1, std::min(source.height, out_w / 2));
    m_levels.push_back(convolve(inputs[k], alpha, out_w, out_h));
  }
}

const Image& PrefilteredEnvironment::image(int k) const {
  return k >= levels() ? m_map->radiance : m_levels[static_cast<std::size_t>(k)];
}

LevelBlend PrefilteredEnvironment::blend(float alpha) const {
  const int last = levels() - 1;
  if (!(alpha > 0.0f)) return {0, 0, 0.0f};
  if (alpha < 1.0f) return {0, 1, alpha};
  if (alpha <= kTopPrefilteredExponent) {
    const float k = std::log2(alpha);
    const int a = std::min(last, 1 + static_cast<int>(std::floor(k)));
    return a == last ? LevelBlend{a, a, 0.0f} : LevelBlend{a, a + 1, k - std::floor(k)};
  }
  const float wb = std::log2(alpha / kTopPrefilteredExponent) /
                   std::log2(kEnvironmentMirrorExponent / kTopPrefilteredExponent);
  return {last, levels(), std::min(wb, 1.0f)};
}

glm::vec3 PrefilteredEnvironment::diffuse(const glm::vec3& n) const {
  const glm::vec2 uv = map_uv(n);
  return diffuse_at(uv.x, uv.y);
}

glm::vec3 PrefilteredEnvironment::specular(const LevelBlend& b, const glm::vec3& r) const {
  const glm::vec2 uv = map_uv(r);
  return specular_at(b, uv.x, uv.y);
}

glm::vec3 PrefilteredEnvironment::diffuse_at(float u, float t) const {
  return map_bilinear<float>(m_levels[1], u, t);
}

glm::vec3 PrefilteredEnvironment::specular_at(const LevelBlend& b, float u, float t) const {
  const glm::vec3 la = map_bilinear<float>(image(b.a), u, t);
  if (b.wb == 0.0f) return la;  // one level (or the map) alone: the second read is not needed
  return la + (map_bilinear<float>(image(b.b), u, t) - la) * b.wb;
}

std::uint64_t PrefilteredEnvironment::bytes() const {
  std::uint64_t total = 0;
  for (const Image& level : m_levels) total += level.pixels.size() * sizeof(glm::vec3);
  return total;
}

std::shared_ptr<const PrefilteredEnvironment> prefiltered_environment(
    const std::shared_ptr<const EnvironmentMap>& map, const PrefilterSettings& settings) {
  // The last few made, most recent last: an editor switching between two maps, or a knob
  // between two resolutions, finds them here.
  static std::mutex mutex;
  static std::vector<std::shared_ptr<const PrefilteredEnvironment>> kept;
  constexpr std::size_t kKept = 4;
  {
    std::lock_guard<std::mutex> lock(mutex);
    for (auto it = kept.begin(); it != kept.end(); ++it) {
      if (&(*it)->map() == map.get() && (*it)->settings() == settings) {
        auto found = *it;
        kept.erase(it);
        kept.push_back(found);
        return found;
      }
    }
  }
  auto made = std::make_shared<const PrefilteredEnvironment>(map, settings);
  std::lock_guard<std::mutex> lock(mutex);
  kept.push_back(made);
  if (kept.size() > kKept) kept.erase(kept.begin());
  return made;
}

}  // namespace gloss
