// The editor's GL pieces without X: float texture upload, and the display shaders' output for
// known inputs read back from an FBO. Expected bytes come from docs/spec/shading.md's encodings
// evaluated here in double precision; GL's float-to-byte conversion may round either way at
// exact halves, so comparisons allow one step.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "editor/gl/display_shader.h"
#include "editor/gl/egl_context.h"
#include "editor/gl/gl_texture.h"
#include "editor/gl/render_target.h"
#include "editor/model/view/heat_map.h"

namespace gloss {
namespace {

class GlDisplay : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!m_context.ok()) GTEST_SKIP() << "no EGL surfaceless GL: " << m_context.error();
  }
  // Draws image through the display shader into a target of the image's size and returns the
  // RGBA bytes, rows top to bottom.
  std::vector<unsigned char> display(const Image& a, const Image* b, const DisplayParams& p) {
    GlTexture ta, tb;
    ta.upload(a);
    if (b != nullptr) tb.upload(*b);
    RenderTarget target;
    target.resize(a.width, a.height);
    target.bind();
    DisplayShader shader;
    shader.draw(ta.id(), b != nullptr ? tb.id() : 0, p);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    const std::vector<unsigned char> bottom_up = target.read_rgba();
    RenderTarget::unbind();
    std::vector<unsigned char> top_down(bottom_up.size());
    const std::size_t row = static_cast<std::size_t>(a.width) * 4;
    for (int y = 0; y < a.height; ++y) {
      std::copy_n(&bottom_up[(a.height - 1 - y) * row], row, &top_down[y * row]);
    }
    return top_down;
  }
  test::EglContext m_context;
};

int byte_of(double value) {
  return static_cast<int>(std::lround(std::clamp(value, 0.0, 1.0) * 255.0));
}

double srgb(double linear) {
  return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

void expect_byte(unsigned char actual, double expected_unit, const char* what) {
  EXPECT_NEAR(static_cast<int>(actual), byte_of(expected_unit), 1) << what;
}

TEST_F(GlDisplay, TextureUploadKeepsFloatsExactly) {
  Image image(3, 2);
  image.at(0, 0) = {0.0f, 1.0f, 2.5f};
  image.at(2, 1) = {1e-6f, 123.25f, 0.333333f};
  GlTexture texture;
  texture.upload(image);
  ASSERT_EQ(texture.width(), 3);
  std::vector<float> back(3 * 2 * 3, -1.0f);
  glBindTexture(GL_TEXTURE_2D, texture.id());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGB, GL_FLOAT, back.data());
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    EXPECT_EQ(back[3 * i + 0], image.pixels[i].x);
    EXPECT_EQ(back[3 * i + 1], image.pixels[i].y);
    EXPECT_EQ(back[3 * i + 2], image.pixels[i].z);
  }
  image = Image(5, 1, glm::vec3(0.5f));  // a new size reallocates
  texture.upload(image);
  EXPECT_EQ(texture.width(), 5);
  EXPECT_EQ(texture.height(), 1);
}

TEST_F(GlDisplay, ClassicClampKeepsRowsTopToBottom) {
  Image image(4, 2);
  const float top[4] = {0.0f, 0.2f, 0.6f, 2.0f};
  const float bottom[4] = {1.0f, 0.1f, 0.7f, 0.0f};
  for (int x = 0; x < 4; ++x) {
    image.at(x, 0) = glm::vec3(top[x], top[x] * 0.5f, 0.0f);
    image.at(x, 1) = glm::vec3(bottom[x]);
  }
  const std::vector<unsigned char> rgba = display(image, nullptr, DisplayParams{});
  for (int x = 0; x < 4; ++x) {
    expect_byte(rgba[4 * x + 0], top[x], "top row, red");
    expect_byte(rgba[4 * x + 1], top[x] * 0.5, "top row, green");
    expect_byte(rgba[16 + 4 * x + 2], bottom[x], "bottom row, blue");
  }
}

TEST_F(GlDisplay, ExposureMultipliesByPowersOfTwo) {
  const Image image(2, 2, glm::vec3(0.2f, 0.05f, 0.4f));
  DisplayParams p;
  p.display.gain = 2.0f;  // +1 stop
  std::vector<unsigned char> rgba = display(image, nullptr, p);
  expect_byte(rgba[0], 0.4, "0.2 x 2");
  expect_byte(rgba[1], 0.1, "0.05 x 2");
  expect_byte(rgba[2], 0.8, "0.4 x 2");
  p.display.gain = 0.25f;  // -2 stops
  rgba = display(image, nullptr, p);
  expect_byte(rgba[2], 0.1, "0.4 / 4");
}

TEST_F(GlDisplay, SrgbEncodingFollowsTheStandardCurve) {
  const Image image(2, 1, glm::vec3(0.2f, 0.002f, 0.9f));
  DisplayParams p;
  p.display.srgb = true;
  const std::vector<unsigned char> rgba = display(image, nullptr, p);
  expect_byte(rgba[0], srgb(0.2), "curve part");
  expect_byte(rgba[1], srgb(0.002), "linear part");
  expect_byte(rgba[2], srgb(0.9), "near white");
}

TEST_F(GlDisplay, ClipOverlayStripesOnlyPixelsAboveOne) {
  // 8 x 1: x < 4 at exactly 1 after exposure (shown white), x >= 4 at 1.5 (clipped). The stripes
  // alternate every 4 pixels of x + y, so the clipped pixels are magenta or dark violet, with
  // no green either way.
  Image image(8, 1, glm::vec3(0.5f));
  for (int x = 4; x < 8; ++x) image.at(x, 0) = glm::vec3(0.75f, 0.1f, 0.1f);
  DisplayParams p;
  p.display.gain = 2.0f;
  p.clip_overlay = true;
  const std::vector<unsigned char> rgba = display(image, nullptr, p);
  for (int x = 0; x < 4; ++x) expect_byte(rgba[4 * x + 1], 1.0, "exactly 1 is not clipped");
  for (int x = 4; x < 8; ++x) {
    EXPECT_EQ(rgba[4 * x + 1], 0) << "clipped pixel " << x << " is striped (no green)";
    EXPECT_EQ(rgba[4 * x + 0], rgba[4 * x + 2]) << "magenta or violet at " << x;
  }
  p.clip_overlay = false;
  const std::vector<unsigned char> plain = display(image, nullptr, p);
  expect_byte(plain[4 * 5 + 1], 0.2, "without the overlay the clamp shows 0.1 x 2");
}

// The shader is the GLSL twin of display/display_transform.h: every tone curve, with and without
// sRGB, at exposures up and down, gives the bytes display_byte gives (whose values the display
// tests check by hand), within GL's rounding of one step.
TEST_F(GlDisplay, ToneCurvesAndOrderMatchTheDisplayTransform) {
  const float values[8] = {0.0f, 0.02f, 0.18f, 0.5f, 1.0f, 3.0f, 7.0f, 40.0f};
  Image image(8, 1);
  for (int x = 0; x < 8; ++x) image.at(x, 0) = glm::vec3(values[x], values[x] * 0.25f, -1.0f);
  for (ToneCurve tone : {ToneCurve::none, ToneCurve::reinhard, ToneCurve::aces}) {
    for (float stops : {-1.0f, 0.0f, 1.5f}) {
      for (bool srgb_on : {false, true}) {
        RenderSettings render;
        render.tone = tone;
        render.exposure = stops;
        render.srgb = srgb_on;
        DisplayParams p;
        p.display = display_transform(render);
        const std::vector<unsigned char> rgba = display(image, nullptr, p);
        for (int x = 0; x < 8; ++x) {
          for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(static_cast<int>(rgba[4 * x + c]),
                        static_cast<int>(display_byte(image.at(x, 0)[c], p.display)), 1)
                << to_string(tone) << " " << stops << " stops, srgb " << srgb_on << ", x " << x
                << " channel " << c;
          }
        }
      }
    }
  }
}

TEST_F(GlDisplay, ClipOverlayFollowsTheToneCurve) {
  // 8 under ACES is above 1 (clipped, striped); under Reinhard nothing clips.
  Image image(8, 1, glm::vec3(8.0f, 0.0f, 0.0f));
  DisplayParams p;
  p.clip_overlay = true;
  p.display.tone = ToneCurve::aces;
  std::vector<unsigned char> rgba = display(image, nullptr, p);
  for (int x = 0; x < 8; ++x) EXPECT_EQ(rgba[4 * x + 0], rgba[4 * x + 2]) << "striped at " << x;
  p.display.tone = ToneCurve::reinhard;
  rgba = display(image, nullptr, p);
  for (int x = 0; x < 8; ++x) expect_byte(rgba[4 * x + 0], 8.0 / 9.0, "Reinhard: 8 / 9");
}

TEST_F(GlDisplay, SumModeAddsTheTwoTerms) {
  const Image emissive(2, 2, glm::vec3(0.1f, 0.0f, 0.5f));
  const Image ambient(2, 2, glm::vec3(0.3f, 0.2f, 0.7f));
  DisplayParams p;
  p.mode = DisplayMode::sum;
  const std::vector<unsigned char> rgba = display(emissive, &ambient, p);
  expect_byte(rgba[0], 0.4, "0.1 + 0.3");
  expect_byte(rgba[1], 0.2, "0 + 0.2");
  expect_byte(rgba[2], 1.0, "0.5 + 0.7 clamps");
}

TEST_F(GlDisplay, HeatMapShowsTheLargestChannelDifferenceOnTheRamp) {
  const Image a(2, 2, glm::vec3(0.5f, 0.1f, 0.1f));
  const Image b(2, 2, glm::vec3(0.3f, 0.15f, 0.1f));  // largest |a - b| = 0.2 (red)
  DisplayParams p;
  p.mode = DisplayMode::heat;
  // scale -> the ramp stop that 0.2 / scale lands on (t = 1, 1/4, 1/2; 0.002 is within a
  // byte of the first stop).
  for (const auto& [scale, stop] :
       {std::pair{0.2f, 4}, std::pair{0.8f, 1}, std::pair{0.4f, 2}, std::pair{100.0f, 0}}) {
    p.heat_scale = scale;
    const std::vector<unsigned char> rgba = display(a, &b, p);
    const glm::vec3 expected = kHeatRamp[stop];
    expect_byte(rgba[0], expected.x, "heat red");
    expect_byte(rgba[1], expected.y, "heat green");
    expect_byte(rgba[2], expected.z, "heat blue");
  }
}

}  // namespace
}  // namespace gloss
