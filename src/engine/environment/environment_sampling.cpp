#include "engine/environment/environment_sampling.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <utility>

#include <glm/geometric.hpp>

namespace gloss {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Two unit vectors completing unit axis to an orthonormal frame.
void frame_of(const glm::dvec3& axis, glm::dvec3& a, glm::dvec3& b) {
  const glm::dvec3 hint = std::abs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  a = glm::normalize(glm::cross(hint, axis));
  b = glm::cross(axis, a);
}

double max_channel(const glm::vec3& c) {
  return std::max(c.x, std::max(c.y, c.z));
}

}  // namespace

EnvironmentSampler::EnvironmentSampler(const EnvironmentMap& map)
    : m_width(map.radiance.width), m_height(map.radiance.height) {
  const Image& image = map.radiance;
  m_weight.resize(image.pixels.size());
  m_row_cdf.assign(static_cast<std::size_t>(m_height) + 1, 0.0);
  m_col_cdf.assign(static_cast<std::size_t>(m_height) * (m_width + 1), 0.0);
  for (int j = 0; j < m_height; ++j) {
    const double sin_theta = std::sin(kPi * (j + 0.5) / m_height);
    double row = 0.0;
    for (int i = 0; i < m_width; ++i) {
      double brightest = 0.0;
      for (int dj = -1; dj <= 1; ++dj) {
        const int jj = std::clamp(j + dj, 0, m_height - 1);
        for (int di = -1; di <= 1; ++di) {
          const int ii = ((i + di) % m_width + m_width) % m_width;
          brightest = std::max(brightest, max_channel(image.at(ii, jj)));
        }
      }
      const double weight = brightest * sin_theta;
      m_weight[static_cast<std::size_t>(j) * m_width + i] = static_cast<float>(weight);
      row += weight;
      m_col_cdf[static_cast<std::size_t>(j) * (m_width + 1) + i + 1] = row;
    }
    for (int i = 1; i <= m_width; ++i) {
      double& c = m_col_cdf[static_cast<std::size_t>(j) * (m_width + 1) + i];
      c = row > 0.0 ? c / row : double(i) / m_width;
    }
    m_row_cdf[static_cast<std::size_t>(j) + 1] = m_row_cdf[static_cast<std::size_t>(j)] + row;
  }
  m_total = m_row_cdf.back();
  if (m_total > 0.0) {
    for (double& c : m_row_cdf) c /= m_total;
  }
}

glm::dvec3 EnvironmentSampler::sample(double u1, double u2, double& pdf) const {
  // The row, then the column within it; what is left of each number places the point in the
  // texel.
  const auto row_at = std::upper_bound(m_row_cdf.begin() + 1, m_row_cdf.end(), u1);
  const int j = std::min(m_height - 1, static_cast<int>(row_at - m_row_cdf.begin()) - 1);
  const double r0 = m_row_cdf[static_cast<std::size_t>(j)], r1 = m_row_cdf[static_cast<std::size_t>(j) + 1];
  const double fy = r1 > r0 ? std::clamp((u1 - r0) / (r1 - r0), 0.0, 1.0) : 0.5;
  const double* cdf = m_col_cdf.data() + static_cast<std::size_t>(j) * (m_width + 1);
  const double* col_at = std::upper_bound(cdf + 1, cdf + m_width + 1, u2);
  const int i = std::min(m_width - 1, static_cast<int>(col_at - cdf) - 1);
  const double fx = cdf[i + 1] > cdf[i] ? std::clamp((u2 - cdf[i]) / (cdf[i + 1] - cdf[i]), 0.0, 1.0)
                                        : 0.5;
  const double u = (i + fx) / m_width, t = (j + fy) / m_height;
  const glm::dvec3 m = map_direction<double>(u, t);
  pdf = this->pdf(m);
  return m;
}

double EnvironmentSampler::pdf(const glm::dvec3& m) const {
  if (!(m_total > 0.0)) return 0.0;
  const glm::dvec2 uv = map_uv(m);
  const int i = std::clamp(static_cast<int>(uv.x * m_width), 0, m_width - 1);
  const int j = std::clamp(static_cast<int>(uv.y * m_height), 0, m_height - 1);
  const double sin_theta = std::sin(uv.y * kPi);
  if (!(sin_theta > 0.0)) return 0.0;
  const double p_uv = m_weight[static_cast<std::size_t>(j) * m_width + i] / m_total *
                      double(m_width) * m_height;
  return p_uv / (2.0 * kPi * kPi * sin_theta);
}

std::uint64_t EnvironmentSampler::bytes() const {
  return m_weight.size() * sizeof(float) + (m_row_cdf.size() + m_col_cdf.size()) * sizeof(double);
}

std::shared_ptr<const EnvironmentSampler> environment_sampler(
    const std::shared_ptr<const EnvironmentMap>& map) {
  // Each entry holds its map, so an address cannot be reused while kept.
  static std::mutex mutex;
  static std::vector<std::pair<std::shared_ptr<const EnvironmentMap>,
                               std::shared_ptr<const EnvironmentSampler>>>
      kept;
  std::lock_guard<std::mutex> lock(mutex);
  for (const auto& [key, sampler] : kept) {
    if (key == map) return sampler;
  }
  auto made = std::make_shared<const EnvironmentSampler>(*map);
  kept.emplace_back(map, made);
  if (kept.size() > 3) kept.erase(kept.begin());
  return made;
}

glm::dvec3 sample_cosine(const glm::dvec3& n, double u1, double u2, double& pdf) {
  glm::dvec3 a, b;
  frame_of(n, a, b);
  const double r = std::sqrt(u1), phi = 2.0 * kPi * u2;
  const double z = std::sqrt(std::max(0.0, 1.0 - u1));
  const glm::dvec3 w = r * std::cos(phi) * a + r * std::sin(phi) * b + z * n;
  pdf = z / kPi;
  return w;
}

double pdf_cosine(const glm::dvec3& n, const glm::dvec3& w) {
  return std::max(0.0, glm::dot(n, w)) / kPi;
}

glm::dvec3 sample_power_cosine(const glm::dvec3& axis, double alpha, double u1, double u2,
                               double& pdf) {
  glm::dvec3 a, b;
  frame_of(axis, a, b);
  // cos = u^(1 / (alpha + 1)), its distance from 1 through expm1 so that alpha = 1e6 keeps it.
  const double one_minus = -std::expm1(std::log(std::max(u1, 1e-300)) / (alpha + 1.0));
  const double c = 1.0 - one_minus;
  const double s = std::sqrt(std::max(0.0, one_minus * (2.0 - one_minus)));
  const double phi = 2.0 * kPi * u2;
  pdf = (alpha + 1.0) / (2.0 * kPi) * std::pow(std::max(c, 0.0), alpha);
  return s * std::cos(phi) * a + s * std::sin(phi) * b + c * axis;
}

double pdf_power_cosine(const glm::dvec3& axis, double alpha, const glm::dvec3& w) {
  const double c = glm::dot(axis, w);
  if (!(c > 0.0)) return 0.0;
  return (alpha + 1.0) / (2.0 * kPi) * (alpha == 0.0 ? 1.0 : std::pow(std::min(c, 1.0), alpha));
}

glm::dvec3 sample_blinn(const glm::dvec3& n, const glm::dvec3& v, double alpha, double u1,
                        double u2, double& pdf) {
  double pdf_h = 0.0;
  const glm::dvec3 h = sample_power_cosine(n, alpha, u1, u2, pdf_h);
  const double vh = glm::dot(v, h);
  if (!(vh > 0.0)) {
    pdf = 0.0;
    return n;
  }
  pdf = pdf_h / (4.0 * vh);
  return glm::normalize(2.0 * vh * h - v);
}

double pdf_blinn(const glm::dvec3& n, const glm::dvec3& v, double alpha, const glm::dvec3& w) {
  const glm::dvec3 sum = w + v;
  const double len = glm::length(sum);
  if (!(len > 0.0)) return 0.0;
  const glm::dvec3 h = sum / len;
  const double vh = glm::dot(v, h);
  if (!(vh > 0.0)) return 0.0;
  return pdf_power_cosine(n, alpha, h) / (4.0 * vh);
}

glm::dvec3 EnvironmentSums::Term::error(long long steps) const {
  if (steps < 2 || !(y > 0.0)) return glm::dvec3(0.0);
  const double n = double(steps);
  const glm::dvec3 r = x / y;
  const glm::dvec3 spread = (xx - 2.0 * r * xy + r * r * yy) / n;
  const double mean_y = y / n;
  return glm::sqrt(glm::max(spread, glm::dvec3(0.0)) / n) / mean_y;
}

EnvironmentDraws environment_draws(const EnvironmentHit& hit, const Environment& environment,
                                   const EnvironmentRotation<double>& rotation,
                                   const EnvironmentSampler& sampler, const double (&u)[6]) {
  EnvironmentDraws d;
  const bool phong = hit.model == ShadingModel::phong;
  const bool map = sampler.active();
  bool drawn[EnvironmentDraws::kCount] = {hit.diffuse, hit.specular, map};
  double p = 0.0;
  if (hit.diffuse) d.w[0] = sample_cosine(hit.n, u[0], u[1], p);
  if (hit.specular) {
    d.w[1] = phong ? sample_power_cosine(hit.r, hit.alpha, u[2], u[3], p)
                   : sample_blinn(hit.n, hit.v, hit.alpha, u[2], u[3], p);
    drawn[1] = p > 0.0;
  }
  if (map) d.w[2] = from_map_frame(sampler.sample(u[4], u[5], p), rotation);
  for (int k = 0; k < EnvironmentDraws::kCount; ++k) {
    d.diffuse[k] = d.specular[k] = glm::dvec3(0.0);
    if (!drawn[k]) continue;
    const glm::dvec3& w = d.w[k];
    // The balance heuristic: every strategy that draws, at this direction.
    double sum = 0.0;
    if (hit.diffuse) sum += pdf_cosine(hit.n, w);
    if (hit.specular) {
      sum += phong ? pdf_power_cosine(hit.r, hit.alpha, w) : pdf_blinn(hit.n, hit.v, hit.alpha, w);
    }
    if (map) sum += sampler.pdf(to_map_frame(w, rotation));
    if (!(sum > 0.0)) continue;
    const double fd = hit.diffuse ? std::max(0.0, glm::dot(hit.n, w)) / kPi : 0.0;
    const double fs =
        hit.specular ? specular_lobe<double>(hit.model, hit.n, hit.v, hit.r, hit.alpha, w) : 0.0;
    if (fd == 0.0 && fs == 0.0) continue;
    const glm::dvec2 uv = map_uv(to_map_frame(w, rotation));
    const glm::dvec3 radiance = map_bilinear<double>(environment.map->radiance, uv.x, uv.y);
    d.diffuse_norm[k] = fd / sum;
    d.specular_norm[k] = fs / sum;
    d.diffuse[k] = radiance * d.diffuse_norm[k];
    d.specular[k] = radiance * d.specular_norm[k];
    d.carries[k] = radiance != glm::dvec3(0.0);
  }
  return d;
}

void add_draws(const EnvironmentDraws& draws, const bool (&visible)[EnvironmentDraws::kCount],
               EnvironmentSums& sums) {
  glm::dvec3 xd(0.0), xs(0.0);
  double yd = 0.0, ys = 0.0;
  for (int k = 0; k < EnvironmentDraws::kCount; ++k) {
    if (visible[k]) {
      xd += draws.diffuse[k];
      xs += draws.specular[k];
    }
    yd += draws.diffuse_norm[k];
    ys += draws.specular_norm[k];
  }
  auto add = [](EnvironmentSums::Term& t, const glm::dvec3& x, double y) {
    t.x += x;
    t.xx += x * x;
    t.xy += x * y;
    t.y += y;
    t.yy += y * y;
  };
  add(sums.diffuse, xd, yd);
  add(sums.specular, xs, ys);
  ++sums.steps;
}

}  // namespace gloss
