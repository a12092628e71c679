// The raster path's settings (editor/model/view/raster_settings.h): the names scripts and the
// settings line use for the renderer choice and the shading frequency, and the equality the
// viewport uses to decide whether a raster frame is out of date.
#include <gtest/gtest.h>

#include <string>

#include "editor/model/view/raster_settings.h"

namespace gloss {
namespace {

TEST(RasterSettings, RendererChoiceNamesAreTheScriptWords) {
  EXPECT_STREQ(to_string(RendererChoice::cpu), "cpu");
  EXPECT_STREQ(to_string(RendererChoice::gl), "gl");
  EXPECT_STREQ(to_string(RendererChoice::automatic), "auto");
  for (RendererChoice c : {RendererChoice::cpu, RendererChoice::gl, RendererChoice::automatic}) {
    RendererChoice parsed = c == RendererChoice::cpu ? RendererChoice::gl : RendererChoice::cpu;
    EXPECT_TRUE(parse_renderer_choice(to_string(c), parsed)) << to_string(c);
    EXPECT_EQ(parsed, c);
  }
}

TEST(RasterSettings, UnknownRendererNamesAreRefusedAndLeaveTheValue) {
  for (const char* name : {"", "automatic", "GL", "raster", "cpu "}) {
    RendererChoice choice = RendererChoice::gl;
    EXPECT_FALSE(parse_renderer_choice(name, choice)) << name;
    EXPECT_EQ(choice, RendererChoice::gl);
  }
}

TEST(RasterSettings, ShadingFrequencyNamesRoundTrip) {
  EXPECT_STREQ(to_string(ShadingFrequency::pixel), "pixel");
  EXPECT_STREQ(to_string(ShadingFrequency::vertex), "vertex");
  ShadingFrequency f = ShadingFrequency::pixel;
  EXPECT_TRUE(parse_shading_frequency("vertex", f));
  EXPECT_EQ(f, ShadingFrequency::vertex);
  EXPECT_TRUE(parse_shading_frequency("pixel", f));
  EXPECT_EQ(f, ShadingFrequency::pixel);
  EXPECT_FALSE(parse_shading_frequency("gouraud", f));
  EXPECT_FALSE(parse_shading_frequency("Pixel", f));
  EXPECT_EQ(f, ShadingFrequency::pixel);
}

TEST(RasterSettings, EqualityComparesEveryKnob) {
  const RasterSettings base;
  EXPECT_TRUE(base == RasterSettings{});
  RasterSettings other = base;
  other.shading = ShadingFrequency::vertex;
  EXPECT_TRUE(base != other);
  other = base;
  other.shadow_map_size = 512;
  EXPECT_TRUE(base != other);
  other = base;
  other.shadow_bias = 0.0f;
  EXPECT_TRUE(base != other);
}

}  // namespace
}  // namespace gloss
