#include "editor/model/export/sheet_labels.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <stb_easy_font.h>

namespace gloss {

namespace {

// stb_easy_font's vertex: x, y, z, RGBA bytes; four per quad.
struct FontVertex {
  float x, y, z;
  unsigned char rgba[4];
};
static_assert(sizeof(FontVertex) == 16, "stb_easy_font writes 16-byte vertices");

}  // namespace

int label_width(const std::string& text, int scale) {
  std::string copy = text;  // the C API takes char*
  return stb_easy_font_width(copy.data()) * scale;
}

int label_height(int scale) {
  return 12 * scale;  // stb_easy_font's line height for text without descender rows
}

void draw_label(Image& image, int x, int y, const std::string& text, glm::vec3 colour, int scale) {
  std::string copy = text;
  // About 270 bytes per character (stb_easy_font's own estimate); twice that for safety.
  std::vector<FontVertex> quads(copy.size() * 40 + 16);
  const int count = stb_easy_font_print(0.0f, 0.0f, copy.data(), nullptr, quads.data(),
                                        static_cast<int>(quads.size() * sizeof(FontVertex)));
  for (int q = 0; q < count; ++q) {
    const FontVertex* v = &quads[static_cast<std::size_t>(q) * 4];
    // Corners 0 and 2 are opposite; font units are whole numbers.
    const int x0 = x + static_cast<int>(std::lround(std::min(v[0].x, v[2].x))) * scale;
    const int x1 = x + static_cast<int>(std::lround(std::max(v[0].x, v[2].x))) * scale;
    const int y0 = y + static_cast<int>(std::lround(std::min(v[0].y, v[2].y))) * scale;
    const int y1 = y + static_cast<int>(std::lround(std::max(v[0].y, v[2].y))) * scale;
    for (int py = std::max(y0, 0); py < std::min(y1, image.height); ++py) {
      for (int px = std::max(x0, 0); px < std::min(x1, image.width); ++px) {
        image.at(px, py) = colour;
      }
    }
  }
}

}  // namespace gloss
