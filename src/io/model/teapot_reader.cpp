#include "io/model/teapot_reader.h"

#include <array>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include "base/assets.h"
#include "base/error.h"
#include "base/text/number_words.h"

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

}  // namespace gloss
