#pragma once
// Linear RGB float images, row 0 at the top.
#include <cstddef>
#include <vector>

#include <glm/vec3.hpp>

namespace gloss {

struct Image {
  int width = 0, height = 0;
  std::vector<glm::vec3> pixels;  // width * height, row-major, top row first

  Image() = default;
  Image(int w, int h, glm::vec3 fill = glm::vec3(0.0f))
      : width(w), height(h), pixels(static_cast<std::size_t>(w) * h, fill) {}
  glm::vec3& at(int x, int y) { return pixels[static_cast<std::size_t>(y) * width + x]; }
  const glm::vec3& at(int x, int y) const {
    return pixels[static_cast<std::size_t>(y) * width + x];
  }
};

// The spec's term buffers (summed over lights) and their total, for one render.
struct TermImages {
  Image emissive, ambient, diffuse, specular;
  Image total;  // emissive + ambient + diffuse + specular, plus background where rays missed
};

enum class Term { emissive, ambient, diffuse, specular, total };
const char* to_string(Term term);
const Image& term_image(const TermImages& terms, Term term);

}  // namespace gloss
