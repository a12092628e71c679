#pragma once
// Planted errors for the raster tests: a renderer whose shader sources have one piece of text
// replaced, so a test can show that its check fails when the shader is wrong.
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "editor/gl/raster/raster_renderer.h"

namespace gloss::test {

// Runs check with a renderer whose shaders have `from` replaced by `to` (which must occur).
inline void with_planted_error(const std::string& from, const std::string& to,
                               const std::function<void(RasterRenderer&)>& check) {
  bool found = false;
  RasterRenderer planted([&](const std::string& text) {
    const std::size_t at = text.find(from);
    if (at == std::string::npos) return text;
    found = true;
    std::string edited = text;
    edited.replace(at, from.size(), to);
    return edited;
  });
  ASSERT_TRUE(found) << "the planted text is not in the shaders any more: " << from;
  check(planted);
}

}  // namespace gloss::test
