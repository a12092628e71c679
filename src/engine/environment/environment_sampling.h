#pragma once
// Directions for the environment's exact terms (docs/engine.md, "The environment"): drawn from the
// clamped cosine about n, from the specular lobe (Phong's about r, Blinn-Phong's through the half
// vector about n) and from the map (texels in proportion to their brightness), and combined with
// the balance heuristic, so neither a sharp lobe nor a small sun is noisy. The progressive
// renderer and the reference path's shadowed estimate both draw through these.
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/vec3.hpp>

#include "scene/environment.h"
#include "scene/render_settings.h"
#include "shading/environment.h"

namespace gloss {

// The map's texels drawn in proportion to their luminance times sin(theta) (their solid
// angle). A texel's weight is the largest luminance of it and its 8 neighbours, so every place
// where the bilinear map is not 0 has a density above 0 (the estimate stays unbiased).
class EnvironmentSampler {
 public:
  explicit EnvironmentSampler(const EnvironmentMap& map);

  // Whether the map has any light to draw (a black map draws nothing: pdf 0 everywhere).
  bool active() const { return m_total > 0.0; }
  // A unit map-frame direction from two uniform numbers in [0, 1), and its solid-angle density.
  glm::dvec3 sample(double u1, double u2, double& pdf) const;
  // The solid-angle density of a unit map-frame direction.
  double pdf(const glm::dvec3& m) const;
  std::uint64_t bytes() const;

 private:
  int m_width = 0, m_height = 0;
  double m_total = 0.0;
  std::vector<double> m_row_cdf;  // H + 1 entries, 0 .. 1
  std::vector<double> m_col_cdf;  // H rows of W + 1 entries, 0 .. 1
  std::vector<float> m_weight;    // per texel, sum m_total
};

// The sampler of map, shared: made the first time and kept for the last few maps.
std::shared_ptr<const EnvironmentSampler> environment_sampler(
    const std::shared_ptr<const EnvironmentMap>& map);

// Unit directions about an axis. Each returns the direction for two uniform numbers and its
// solid-angle density; pdf_* gives the density of a direction.
glm::dvec3 sample_cosine(const glm::dvec3& n, double u1, double u2, double& pdf);
double pdf_cosine(const glm::dvec3& n, const glm::dvec3& w);
// cos^alpha about axis over the half-sphere around it: density (alpha + 1) / (2 pi) cos^alpha.
glm::dvec3 sample_power_cosine(const glm::dvec3& axis, double alpha, double u1, double u2,
                               double& pdf);
double pdf_power_cosine(const glm::dvec3& axis, double alpha, const glm::dvec3& w);
// Blinn-Phong: the half vector h drawn as cos^alpha about n, w the mirror of v about h; density
// pdf_h / (4 |v.h|). pdf 0 (and any w) when the draw gives no direction.
glm::dvec3 sample_blinn(const glm::dvec3& n, const glm::dvec3& v, double alpha, double u1,
                        double u2, double& pdf);
double pdf_blinn(const glm::dvec3& n, const glm::dvec3& v, double alpha, const glm::dvec3& w);

// What one hit needs for the environment's exact terms.
struct EnvironmentHit {
  glm::dvec3 n, v, r;  // unit shading normal, direction to the eye, mirror direction
  double alpha = 0.0;  // the material's shininess
  ShadingModel model = ShadingModel::phong;
  bool diffuse = true, specular = true;  // kd, ks not zero
};

// Running sums of the self-normalised estimates: diffuse.value() (the contract's (1 / pi)
// integral of L max(0, n.w) vis) and specular.value() (integral of L lobe vis over integral of
// lobe), both at intensity 1, with their error bars (the reference path reports them).
struct EnvironmentSums {
  // Per term: sums over steps of X (the step's contribution, per channel) and Y (its
  // normaliser), and of X^2, X Y and Y^2 for the error bar.
  struct Term {
    glm::dvec3 x{0.0}, xx{0.0}, xy{0.0};
    double y = 0.0, yy = 0.0;
    glm::dvec3 value() const { return y > 0.0 ? x / y : glm::dvec3(0.0); }
    // The ratio's standard error over `steps` steps (delta method), per channel.
    glm::dvec3 error(long long steps) const;
  };
  Term diffuse, specular;
  long long steps = 0;
};

// The three directions of one step (drawn from the cosine, the lobe and the map) and what each
// carries before visibility, with the balance heuristic over the three densities: f L / (sum of
// densities) towards each term's sum and f / (sum of densities) towards its normaliser.
struct EnvironmentDraws {
  static constexpr int kCount = 3;
  glm::dvec3 w[kCount];  // unit world directions
  glm::dvec3 diffuse[kCount], specular[kCount];
  double diffuse_norm[kCount] = {}, specular_norm[kCount] = {};
  bool carries[kCount] = {};  // some light towards a term: visibility matters
};

// One step's draws at a hit from six uniform numbers in [0, 1); radiance at intensity 1.
EnvironmentDraws environment_draws(const EnvironmentHit& hit, const Environment& environment,
                                   const EnvironmentRotation<double>& rotation,
                                   const EnvironmentSampler& sampler, const double (&u)[6]);

// Adds the draws to sums, direction k counted as seen when visible[k] (1) and as blocked (0)
// otherwise; the normalisers take every draw (they are integrals of the lobes alone).
void add_draws(const EnvironmentDraws& draws, const bool (&visible)[EnvironmentDraws::kCount],
               EnvironmentSums& sums);

}  // namespace gloss
