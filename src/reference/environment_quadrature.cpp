#include "reference/environment_quadrature.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <queue>

#include <tbb/parallel_for.h>
#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include "reference/lobe_sum.h"
#include "reference/quadrature_cells.h"
#include "shading/environment.h"

namespace gloss {

namespace {

using quadrature::Lobe;
using quadrature::Moments;

constexpr double kPi = 3.14159265358979323846;
constexpr long long kCellBudget = 500000;  // cells per integral before it stops where it is

double max_channel(const glm::dvec3& v) {
  return std::max(v.x, std::max(v.y, v.z));
}

// A cell: a block of whole texels (level >= 0, (i, j) in that level's grid) or (level -1) a
// rectangle inside one bilinear piece of a texel.
struct Cell {
  int level = 0, i = 0, j = 0;
  double u0 = 0, u1 = 0, t0 = 0, t1 = 0;
  glm::dvec3 value{0.0}, error{0.0};
  double priority = 0.0;
  bool operator<(const Cell& o) const { return priority < o.priority; }
};

}  // namespace

// Levels of texel blocks: level 0 the texels, level k blocks of 2^k x 2^k texels (clipped at the
// map's edges), up to a top level at most 8 x 4; per block its moments and cone.
struct EnvironmentQuadrature::Tree {
  std::shared_ptr<const EnvironmentMap> map;
  int width = 0, height = 0;
  std::vector<std::vector<Moments>> moments;
  std::vector<std::vector<glm::dvec4>> cones;  // centre, radius
  std::vector<int> level_width, level_height;

  void place(Cell& c) const {
    const int size = 1 << c.level;
    c.u0 = double(c.i * size) / width;
    c.u1 = double(std::min(width, (c.i + 1) * size)) / width;
    c.t0 = double(c.j * size) / height;
    c.t1 = double(std::min(height, (c.j + 1) * size)) / height;
  }

  void children(const Cell& c, std::vector<Cell>& out) const {
    out.clear();
    if (c.level > 0) {
      const int k = c.level - 1;
      for (int dj = 0; dj < 2; ++dj) {
        for (int di = 0; di < 2; ++di) {
          Cell child;
          child.level = k;
          child.i = 2 * c.i + di;
          child.j = 2 * c.j + dj;
          if (child.i >= level_width[static_cast<std::size_t>(k)] ||
              child.j >= level_height[static_cast<std::size_t>(k)]) {
            continue;
          }
          place(child);
          out.push_back(child);
        }
      }
      return;
    }
    // A texel splits at its centre (where L's bilinear pieces meet), a piece into quarters.
    const double um = 0.5 * (c.u0 + c.u1), tm = 0.5 * (c.t0 + c.t1);
    const double us[3] = {c.u0, um, c.u1}, ts[3] = {c.t0, tm, c.t1};
    for (int dj = 0; dj < 2; ++dj) {
      for (int di = 0; di < 2; ++di) {
        Cell child;
        child.level = -1;
        child.u0 = us[di];
        child.u1 = us[di + 1];
        child.t0 = ts[dj];
        child.t1 = ts[dj + 1];
        out.push_back(child);
      }
    }
  }

  // The lobe sampled (3 x 3 Gauss-Legendre) over c's bilinear pieces; with its pieces' quarters
  // too, which is the value kept, their difference the error estimate.
  void sampled(const Lobe& lobe, bool unit, Cell& c) const {
    std::vector<Cell> pieces, quarters;
    if (c.level == 0) {
      children(c, pieces);
    } else {
      pieces.push_back(c);
    }
    glm::dvec3 coarse(0.0), fine(0.0);
    const Image& image = map->radiance;
    for (const Cell& p : pieces) {
      coarse += quadrature::sampled_integral(image, unit, lobe, p.u0, p.u1, p.t0, p.t1);
      children(p, quarters);
      for (const Cell& q : quarters) {
        fine += quadrature::sampled_integral(image, unit, lobe, q.u0, q.u1, q.t0, q.t1);
      }
    }
    c.value = fine;
    c.error = glm::abs(fine - coarse);
  }

  // Sets c's value and error: a bound on smooth cells, the midpoint of [0, f_max] on blocks an
  // edge crosses (they are split down to texels), the sampled estimate on texels and their
  // pieces where the Taylor bound does not apply. false when the lobe is 0 on c.
  bool evaluate(const Lobe& lobe, bool unit, Cell& c) const {
    glm::dvec3 centre;
    double radius;
    Moments m;
    if (c.level >= 0) {
      const std::size_t at =
          static_cast<std::size_t>(c.j) * level_width[static_cast<std::size_t>(c.level)] + c.i;
      const glm::dvec4& cone = cones[static_cast<std::size_t>(c.level)][at];
      centre = glm::dvec3(cone);
      radius = cone.w;
      m = (unit ? quadrature::unit_moments(c.u0, c.u1, c.t0, c.t1)
                : moments[static_cast<std::size_t>(c.level)][at])
              .about(centre);
    } else {
      quadrature::cone_of(c.u0, c.u1, c.t0, c.t1, centre, radius);
      m = quadrature::rectangle_moments(map->radiance, unit, c.u0, c.u1, c.t0, c.t1, centre);
    }
    const Lobe::Part part = lobe.on(m, centre, radius);
    if (part.zero) return false;
    const bool taylor = part.smooth && !lobe.blinn;
    if (taylor || c.level > 0) {
      c.value = part.value;
      c.error = part.error;
    } else {
      sampled(lobe, unit, c);
    }
    return true;
  }

  QuadratureResult integrate(const Lobe& lobe, bool unit, double tolerance) const {
    std::priority_queue<Cell> queue;
    QuadratureResult result;
    auto add = [&](Cell& c) {
      if (!evaluate(lobe, unit, c)) return;
      c.priority = max_channel(c.error);
      result.value += c.value;
      result.bound += c.error;
      ++result.cells;
      if (c.priority > 0.0) queue.push(c);
    };
    const std::size_t top = moments.size() - 1;
    for (int j = 0; j < level_height[top]; ++j) {
      for (int i = 0; i < level_width[top]; ++i) {
        Cell c;
        c.level = static_cast<int>(top);
        c.i = i;
        c.j = j;
        place(c);
        add(c);
      }
    }
    std::vector<Cell> kids;
    while (!queue.empty() && result.cells < kCellBudget) {
      const double scale = std::max(max_channel(glm::abs(result.value)), 1e-300);
      if (max_channel(result.bound) <= tolerance * scale) break;
      const Cell c = queue.top();
      queue.pop();
      result.value -= c.value;
      result.bound -= c.error;
      children(c, kids);
      for (Cell& k : kids) add(k);
    }
    result.bound = glm::max(result.bound, glm::dvec3(0.0));
    return result;
  }
};

EnvironmentQuadrature::EnvironmentQuadrature(std::shared_ptr<const EnvironmentMap> map)
    : m_tree(std::make_unique<Tree>()) {
  Tree& t = *m_tree;
  t.map = std::move(map);
  const Image& image = t.map->radiance;
  t.width = image.width;
  t.height = image.height;
  std::vector<Moments> texels(image.pixels.size());
  tbb::parallel_for(0, image.height, [&](int j) {
    for (int i = 0; i < image.width; ++i) {
      // The texel's four bilinear pieces.
      const double u0 = double(i) / image.width, u1 = double(i + 1) / image.width;
      const double t0 = double(j) / image.height, t1 = double(j + 1) / image.height;
      const double um = 0.5 * (u0 + u1), tm = 0.5 * (t0 + t1);
      const glm::dvec3 origin(0.0);
      Moments m = quadrature::rectangle_moments(image, false, u0, um, t0, tm, origin);
      m += quadrature::rectangle_moments(image, false, um, u1, t0, tm, origin);
      m += quadrature::rectangle_moments(image, false, u0, um, tm, t1, origin);
      m += quadrature::rectangle_moments(image, false, um, u1, tm, t1, origin);
      texels[static_cast<std::size_t>(j) * image.width + i] = m;
    }
  });
  t.moments.push_back(std::move(texels));
  t.level_width.push_back(image.width);
  t.level_height.push_back(image.height);
  while (t.level_width.back() > 8 || t.level_height.back() > 4) {
    const int w = t.level_width.back(), h = t.level_height.back();
    const int cw = (w + 1) / 2, ch = (h + 1) / 2;
    std::vector<Moments> up(static_cast<std::size_t>(cw) * ch);
    const std::vector<Moments>& below = t.moments.back();
    for (int j = 0; j < h; ++j) {
      for (int i = 0; i < w; ++i) {
        up[static_cast<std::size_t>(j / 2) * cw + i / 2] +=
            below[static_cast<std::size_t>(j) * w + i];
      }
    }
    t.moments.push_back(std::move(up));
    t.level_width.push_back(cw);
    t.level_height.push_back(ch);
  }
  for (std::size_t k = 0; k < t.moments.size(); ++k) {
    std::vector<glm::dvec4> cones(t.moments[k].size());
    tbb::parallel_for(0, t.level_height[k], [&](int j) {
      for (int i = 0; i < t.level_width[k]; ++i) {
        Cell c;
        c.level = static_cast<int>(k);
        c.i = i;
        c.j = j;
        t.place(c);
        glm::dvec3 centre;
        double radius;
        quadrature::cone_of(c.u0, c.u1, c.t0, c.t1, centre, radius);
        cones[static_cast<std::size_t>(j) * t.level_width[k] + i] = glm::dvec4(centre, radius);
      }
    });
    t.cones.push_back(std::move(cones));
  }
}

EnvironmentQuadrature::~EnvironmentQuadrature() = default;

QuadratureResult EnvironmentQuadrature::diffuse(const glm::dvec3& n, double tolerance) const {
  Lobe lobe;
  lobe.axis = lobe.n = n;
  lobe.alpha = 1.0;
  QuadratureResult r = m_tree->integrate(lobe, false, tolerance);
  r.value /= kPi;
  r.bound /= kPi;
  return r;
}

namespace {
// The contract's specular lobe of the model at a hit (quadrature_cells.h).
Lobe specular_lobe_at(ShadingModel model, const glm::dvec3& n, const glm::dvec3& v,
                      const glm::dvec3& r, double alpha) {
  Lobe lobe;
  lobe.blinn = model == ShadingModel::blinn_phong;
  lobe.axis = lobe.blinn ? n : r;
  lobe.n = n;
  lobe.v = v;
  lobe.alpha = alpha;
  return lobe;
}
}  // namespace

QuadratureResult EnvironmentQuadrature::specular(ShadingModel model, const glm::dvec3& n,
                                                 const glm::dvec3& v, const glm::dvec3& r,
                                                 double alpha, double tolerance) const {
  const Lobe lobe = specular_lobe_at(model, n, v, r, alpha);
  const QuadratureResult top = m_tree->integrate(lobe, false, tolerance);
  const QuadratureResult bottom = m_tree->integrate(lobe, true, tolerance);
  QuadratureResult out;
  out.cells = top.cells + bottom.cells;
  const double d = bottom.value.x, bd = bottom.bound.x;
  if (!(d > 0.0)) return out;  // no lobe at all (v below the surface)
  out.value = top.value / d;
  out.bound = d > bd ? (top.bound + glm::abs(out.value) * bd) / (d - bd) : glm::dvec3(INFINITY);
  return out;
}

glm::dvec3 EnvironmentQuadrature::specular_sum(ShadingModel model, const glm::dvec3& n,
                                               const glm::dvec3& v, const glm::dvec3& r,
                                               double alpha) const {
  return lobe_mean(m_tree->map->radiance, specular_lobe_at(model, n, v, r, alpha), r);
}

std::uint64_t EnvironmentQuadrature::bytes() const {
  std::uint64_t total = 0;
  for (const auto& level : m_tree->moments) {
    total += level.size() * (sizeof(Moments) + sizeof(glm::dvec4));
  }
  return total;
}

std::shared_ptr<const EnvironmentQuadrature> environment_quadrature(
    const std::shared_ptr<const EnvironmentMap>& map) {
  // The last two maps (each quadrature holds its map, so an address cannot be reused while kept).
  static std::mutex mutex;
  static std::vector<std::shared_ptr<const EnvironmentQuadrature>> kept;
  static std::vector<const EnvironmentMap*> keys;
  std::lock_guard<std::mutex> lock(mutex);
  for (std::size_t k = 0; k < keys.size(); ++k) {
    if (keys[k] == map.get()) return kept[k];
  }
  auto made = std::make_shared<const EnvironmentQuadrature>(map);
  kept.push_back(made);
  keys.push_back(map.get());
  if (kept.size() > 2) {
    kept.erase(kept.begin());
    keys.erase(keys.begin());
  }
  return made;
}

}  // namespace gloss
