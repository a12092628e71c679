#include "teapot.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include <glm/geometric.hpp>

#include "assets.h"
#include "error.h"
#include "number_words.h"

namespace gloss {

namespace {

// The shipped data's layout (assets/models/utah-teapot.txt): patches 20-27 are the lid.
constexpr std::size_t teapot_patch_count = 32;
constexpr std::size_t lid_first = 20, lid_end = 28;
// three.js's empirical factor for the lid's horizontal size; it closes the gap at the rim.
constexpr float lid_scale = 1.077f;

std::vector<std::string> split_words(const std::string& line) {
  std::istringstream in(line.substr(0, line.find('#')));
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}

// Reads the file's lines that are not blank or comments, as words, and knows the current line
// number for errors.
class LineReader {
 public:
  LineReader(std::istream& in, const std::string& path) : m_in(in), m_path(path) {}

  // Next line that is not blank or a comment, split into words; false at end of file.
  bool next(std::vector<std::string>& words) {
    for (std::string line; std::getline(m_in, line);) {
      ++m_line;
      words = split_words(line);
      if (!words.empty()) return true;
    }
    return false;
  }
  [[noreturn]] void fail(const std::string& message) const {
    throw InputError(m_path, message, m_line);
  }
  int line() const { return m_line; }

 private:
  std::istream& m_in;
  const std::string& m_path;
  int m_line = 0;
};

// Scales the file-frame x and y (y-up x and z) of every lid control point. A point the lid shares
// with another patch is duplicated first, so only the lid moves.
void fit_lid(BezierPatches& data) {
  std::vector<bool> used_elsewhere(data.points.size(), false);
  for (std::size_t p = 0; p < data.patches.size(); ++p) {
    if (p >= lid_first && p < lid_end) continue;
    for (int index : data.patches[p]) used_elsewhere[index] = true;
  }
  std::vector<int> moved(data.points.size(), -1);
  for (std::size_t p = lid_first; p < lid_end; ++p) {
    for (int& index : data.patches[p]) {
      if (moved[index] < 0) {
        glm::vec3 q = data.points[index];
        q.x *= lid_scale;
        q.z *= lid_scale;
        if (used_elsewhere[index]) {
          moved[index] = static_cast<int>(data.points.size());
          data.points.push_back(q);
        } else {
          moved[index] = index;
          data.points[index] = q;
        }
      }
      index = moved[index];
    }
  }
}

// Cubic Bezier by de Casteljau. lerp is exact at t = 0 and t = 1 and when a == b, so collapsed
// control rows evaluate to exactly one point (their triangles then have exactly zero area) and
// patches sharing an edge share its corner positions exactly.
glm::dvec3 lerp(const glm::dvec3& a, const glm::dvec3& b, double t) {
  return t < 0.5 ? a + t * (b - a) : b - (1.0 - t) * (b - a);
}

struct CurvePoint {
  glm::dvec3 position;
  glm::dvec3 tangent;  // derivative with respect to the curve parameter
};

CurvePoint eval_cubic(const glm::dvec3 c[4], double t) {
  const glm::dvec3 a = lerp(c[0], c[1], t), b = lerp(c[1], c[2], t), e = lerp(c[2], c[3], t);
  const glm::dvec3 d = lerp(a, b, t), f = lerp(b, e, t);
  return {lerp(d, f, t), 3.0 * (f - d)};
}

struct SurfacePoint {
  glm::dvec3 position;
  glm::dvec3 d_s;  // dP/ds; s selects the control row (0 = first row, 1 = last)
  glm::dvec3 d_t;  // dP/dt; t runs along a control row (0 = first column, 1 = last)
};

SurfacePoint eval_patch(const glm::dvec3 control[16], double s, double t) {
  glm::dvec3 rows[4], row_tangents[4];
  for (int i = 0; i < 4; ++i) {
    const CurvePoint r = eval_cubic(control + 4 * i, t);
    rows[i] = r.position;
    row_tangents[i] = r.tangent;
  }
  const CurvePoint across = eval_cubic(rows, s);
  return {across.position, across.tangent, eval_cubic(row_tangents, s).position};
}

// The data's winding, checked once on the body: in the file's z-up frame a control row runs
// clockwise seen from above and successive rows go down, so cross(dP/dt, dP/ds) points out of the
// teapot; the other patches follow the same convention (the tests check lid, bottom and body).
bool outward_normal(const SurfacePoint& sp, glm::dvec3& n) {
  const glm::dvec3 c = glm::cross(sp.d_t, sp.d_s);
  const double scale = std::max(glm::length(sp.d_t), glm::length(sp.d_s));
  const double len = glm::length(c);
  if (!(len > 1e-10 * scale * scale) || !std::isfinite(len)) return false;
  n = c / len;
  return true;
}

// Where the derivatives' cross product vanishes (a control row or column collapsed to a pole)
// the normal is taken a little way into the patch; the lid's and bottom's poles are flat, so the
// nudge changes the direction by far less than the tessellation does.
glm::vec3 patch_normal(const glm::dvec3 control[16], double s, double t) {
  glm::dvec3 n;
  if (outward_normal(eval_patch(control, s, t), n)) return glm::vec3(n);
  for (double nudge : {1e-3, 1e-2, 1e-1}) {
    const double s2 = s < 0.5 ? s + nudge : s - nudge;
    const double t2 = t < 0.5 ? t + nudge : t - nudge;
    if (outward_normal(eval_patch(control, s2, t2), n)) return glm::vec3(n);
  }
  if (outward_normal(eval_patch(control, 0.5, 0.5), n)) return glm::vec3(n);
  return glm::vec3(0.0f, 1.0f, 0.0f);  // the whole patch is degenerate; its triangles are dropped
}

}  // namespace

BezierPatches load_bezier_patches(const std::string& path) {
  std::error_code fs_error;
  if (std::filesystem::is_directory(path, fs_error)) throw InputError(path, "is a folder");
  std::ifstream file(path);
  if (!file) throw InputError(path, "cannot open file");
  LineReader reader(file, path);
  BezierPatches data;
  std::vector<int> patch_lines;  // file line of each patch, for index errors
  bool have_patches = false, have_points = false;

  std::vector<std::string> words;
  while (reader.next(words)) {
    long count = 0;
    if (words.size() != 2 || (words[0] != "patches" && words[0] != "points") ||
        !parse_long(words[1], count) || count <= 0) {
      reader.fail("expected 'patches N' or 'points N' with N > 0");
    }
    const bool is_patches = words[0] == "patches";
    bool& seen = is_patches ? have_patches : have_points;
    if (seen) reader.fail("repeated '" + words[0] + "' section");
    seen = true;
    for (long k = 0; k < count; ++k) {
      if (!reader.next(words)) {
        reader.fail("file ends after " + std::to_string(k) + " of " + std::to_string(count) + " " +
                    (is_patches ? "patch" : "point") + " lines");
      }
      if (is_patches) {
        std::array<int, 16> patch{};
        long index = 0;
        for (std::size_t i = 0; i < 16; ++i) {
          if (words.size() != 16 || !parse_long(words[i], index) || index < 0 || index > 1 << 30) {
            reader.fail("expected 16 control-point indices (non-negative integers)");
          }
          patch[i] = static_cast<int>(index);
        }
        data.patches.push_back(patch);
        patch_lines.push_back(reader.line());
      } else {
        float x = 0, y = 0, z = 0;
        if (words.size() != 3 || !parse_finite_float(words[0], x) ||
            !parse_finite_float(words[1], y) || !parse_finite_float(words[2], z)) {
          reader.fail("expected a point 'x y z' (three finite numbers)");
        }
        data.points.emplace_back(x, z, -y);  // z-up to y-up, right-handed
      }
    }
  }
  if (!have_patches) throw InputError(path, "no 'patches' section", reader.line());
  if (!have_points) throw InputError(path, "no 'points' section", reader.line());
  for (std::size_t p = 0; p < data.patches.size(); ++p) {
    for (int index : data.patches[p]) {
      if (static_cast<std::size_t>(index) >= data.points.size()) {
        throw InputError(path,
                         "control-point index " + std::to_string(index) + " out of range (" +
                             std::to_string(data.points.size()) + " points)",
                         patch_lines[p]);
      }
    }
  }
  return data;
}

const BezierPatches& teapot_patches() {
  static const BezierPatches patches = [] {
    const std::string path = asset_path("models/utah-teapot.txt");
    BezierPatches data = load_bezier_patches(path);
    if (data.patches.size() != teapot_patch_count) {
      throw InputError(path, "expected the " + std::to_string(teapot_patch_count) +
                                 " patches of the Utah teapot");
    }
    fit_lid(data);
    return data;
  }();
  return patches;
}

// Vertex (i, j) of a patch sits at s = i / level (row direction), t = j / level (column
// direction). Triangles (a, b, c) and (a, c, d) of each grid cell wind like cross(dP/dt, dP/ds),
// the outward normal; a collapsed row or column makes one of the two zero-area, and those are
// dropped.
Mesh tessellate_patches(const BezierPatches& patches, int level, bool smooth) {
  if (level < 1 || level > 64) {
    throw std::invalid_argument("tessellate_patches: level " + std::to_string(level) +
                                " outside 1..64");
  }
  const unsigned n = static_cast<unsigned>(level) + 1;  // vertices per patch side
  Mesh mesh;
  mesh.positions.reserve(patches.patches.size() * n * n);
  if (smooth) mesh.normals.reserve(patches.patches.size() * n * n);
  mesh.triangles.reserve(patches.patches.size() * 2 * level * level);

  for (const std::array<int, 16>& patch : patches.patches) {
    glm::dvec3 control[16];
    for (int k = 0; k < 16; ++k) {
      if (patch[k] < 0 || static_cast<std::size_t>(patch[k]) >= patches.points.size()) {
        throw std::invalid_argument("tessellate_patches: control-point index out of range");
      }
      control[k] = glm::dvec3(patches.points[patch[k]]);
    }
    const auto base = static_cast<unsigned>(mesh.positions.size());
    for (unsigned i = 0; i < n; ++i) {
      const double s = static_cast<double>(i) / level;
      for (unsigned j = 0; j < n; ++j) {
        const double t = static_cast<double>(j) / level;
        mesh.positions.emplace_back(eval_patch(control, s, t).position);
        if (smooth) mesh.normals.push_back(patch_normal(control, s, t));
      }
    }
    for (unsigned i = 0; i + 1 < n; ++i) {
      for (unsigned j = 0; j + 1 < n; ++j) {
        const unsigned a = base + i * n + j, b = a + 1, c = b + n, d = a + n;
        mesh.triangles.emplace_back(a, b, c);
        mesh.triangles.emplace_back(a, c, d);
      }
    }
  }
  drop_degenerate_triangles(mesh);
  return mesh;
}

}  // namespace gloss
