#pragma once
// Text drawn into an exported image: the term sheet's pane names. The glyphs come from
// stb_easy_font (libstb-dev), whose characters are axis-aligned rectangles in a grid about
// 6 pixels wide and 12 high per character at scale 1; each rectangle is filled pixel for pixel.
#include <string>

#include <glm/vec3.hpp>

#include "base/image.h"

namespace gloss {

// Size of text at scale (pixels), as stb_easy_font measures it times scale.
int label_width(const std::string& text, int scale);
int label_height(int scale);

// Draws text with its top left at (x, y), each font unit scale x scale pixels, in colour (linear
// values, written as they are). Pixels outside the image are skipped.
void draw_label(Image& image, int x, int y, const std::string& text, glm::vec3 colour, int scale);

}  // namespace gloss
