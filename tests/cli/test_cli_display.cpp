// gloss-cli render's display transform (docs/spec/scene-and-cli.md: render.exposure, render.tone,
// --exposure, --tone) and its linear outputs (--pfm, --exr): pixel values worked out by hand on a
// scene that is all background, so every pixel is the background colour.
#include <array>
#include <cstdio>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "io/image/image_io.h"
#include "support/cli_run.h"
#include "support/exr_file.h"
#include "support/scratch_folder.h"

namespace gloss {
namespace {

// Every pixel shows the background: linear (0.3, 0.6, 3.0).
const char* const kBackgroundScene = R"({
  "camera": {"eye": [0, 0, 4], "target": [0, 0, 0], "up": [0, 1, 0], "fov_y": 40},
  "lights": [], "materials": {}, "objects": [],
  "background": [0.3, 0.6, 3.0],
  "render": {"width": 8, "height": 6, "spp": 1%s}
})";

class CliDisplay : public ::testing::Test {
 protected:
  // Writes the scene with extra render fields and runs gloss-cli render on it with args, in
  // outputs; returns the exit status, stderr in err.
  int render(const std::string& render_extra, const std::string& args) {
    char scene[1024];
    std::snprintf(scene, sizeof scene, kBackgroundScene, render_extra.c_str());
    std::ofstream(inputs.file("bg.json"), std::ios::binary) << scene;
    const CliRun r =
        run_cli("render '" + inputs.file("bg.json") + "' " + args, logs, outputs.path().string());
    err = r.err;
    return r.status;
  }
  // The first pixel of a PNG in outputs.
  std::array<int, 3> pixel(const std::string& name) const {
    const Png8 png = read_png(outputs.file(name));
    return {png.rgb[0], png.rgb[1], png.rgb[2]};
  }
  std::string settings(const std::string& name) const {
    for (const auto& chunk : read_png(outputs.file(name)).text) {
      if (chunk.first == "gloss:settings") return chunk.second;
    }
    return "";
  }
  ScratchFolder inputs, outputs, logs;
  std::string err;
};

TEST_F(CliDisplay, ExposureAndToneFromTheCommandLine) {
  ASSERT_EQ(render("", "-o r.png --exposure 1 --tone reinhard"), 0) << err;
  // 2 x (0.3, 0.6, 3.0) = (0.6, 1.2, 6); x / (1 + x) = (0.375, 0.5455, 0.8571);
  // x 255 + 0.5, floored: 96, 139, 219.
  EXPECT_EQ(pixel("r.png"), (std::array<int, 3>{96, 139, 219}));
  EXPECT_NE(settings("r.png").find("exposure 1, tone reinhard"), std::string::npos)
      << settings("r.png");

  ASSERT_EQ(render("", "-o a.png --exposure 2 --tone aces --srgb"), 0) << err;
  // 4 x 0.3 = 1.2: 1.2 (2.51 x 1.2 + 0.03) / (1.2 (2.43 x 1.2 + 0.59) + 0.14) = 3.6504 / 4.3472
  // = 0.83971; sRGB: 1.055 x 0.83971^(1/2.4) - 0.055 = 0.92594, x 255 + 0.5 = 236.6 -> 236.
  // G: 2.4 -> 0.93421 -> 0.97051 -> 247.98 -> 247; B: 12 -> 1.0322, clamped to 1 -> 255.
  EXPECT_EQ(pixel("a.png"), (std::array<int, 3>{236, 247, 255}));
}

TEST_F(CliDisplay, TheSceneFileCarriesTheTransformAndOptionsOverrideIt) {
  ASSERT_EQ(render(R"(, "exposure": -1, "tone": "none")", "-o s.png"), 0) << err;
  // Half: (0.15, 0.3, 1.5) -> 38.75, 77, clamped 255.
  EXPECT_EQ(pixel("s.png"), (std::array<int, 3>{38, 77, 255}));
  ASSERT_EQ(render(R"(, "exposure": -1, "tone": "none")", "-o o.png --exposure 0"), 0) << err;
  EXPECT_EQ(pixel("o.png"), (std::array<int, 3>{77, 153, 255}));  // 76.5 -> 77, 153
}

TEST_F(CliDisplay, PfmAndExrHoldTheLinearImageBeforeTheTransform) {
  ASSERT_EQ(render("", "-o t.png --pfm t.pfm --exr t.exr --exposure 3 --tone aces"), 0) << err;
  const Image pfm = read_pfm(outputs.file("t.pfm"));
  const test::ExrFile exr = test::read_exr_file(outputs.file("t.exr"));
  ASSERT_EQ(exr.image.width, 8);
  ASSERT_EQ(exr.image.height, 6);
  for (std::size_t i = 0; i < pfm.pixels.size(); ++i) {
    EXPECT_EQ(pfm.pixels[i], glm::vec3(0.3f, 0.6f, 3.0f));
    EXPECT_EQ(exr.image.pixels[i], pfm.pixels[i]);
  }
}

TEST_F(CliDisplay, BadValuesExitTwoNamingTheOption) {
  EXPECT_EQ(render("", "-o x.png --tone filmic"), 2);
  EXPECT_NE(err.find("--tone"), std::string::npos) << err;
  EXPECT_NE(err.find("filmic"), std::string::npos) << err;
  EXPECT_EQ(render("", "-o x.png --exposure 40"), 2);
  EXPECT_NE(err.find("--exposure"), std::string::npos) << err;
  EXPECT_EQ(render(R"(, "tone": "filmic")", "-o x.png"), 2);
  EXPECT_NE(err.find("tone"), std::string::npos) << err;
  EXPECT_EQ(render(R"(, "exposure": 33)", "-o x.png"), 2);
  EXPECT_NE(err.find("exposure"), std::string::npos) << err;
  EXPECT_TRUE(outputs.entries().empty());
}

}  // namespace
}  // namespace gloss
