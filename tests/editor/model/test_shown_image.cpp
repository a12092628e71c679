// `screenshot PATH shown` (shown_image.h): the frame as it is, linear as PFM, displayed as PNG
// with the scene at the frame's size in its chunks; values made by hand.
#include "editor/model/export/shown_image.h"

#include <filesystem>

#include <gtest/gtest.h>

#include "io/image/image_io.h"
#include "io/image/scene_in_png.h"
#include "support/scratch_folder.h"
#include "support/test_scene.h"

namespace gloss {
namespace {

// A 3 x 2 frame of the two-sphere scene (whose render block says 320 x 240): total 0.25 ... ,
// diffuse a constant 0.1.
RenderedFrame frame_3x2() {
  RenderedFrame f;
  f.info.width = 3;
  f.info.height = 2;
  f.info.spp = 16;
  f.info.converged = true;
  f.images.total = Image(3, 2);
  for (int i = 0; i < 6; ++i) f.images.total.pixels[i] = glm::vec3(0.05f * i, 0.25f, 2.0f);
  f.images.emissive = f.images.ambient = f.images.specular = Image(3, 2, glm::vec3(0.0f));
  f.images.diffuse = Image(3, 2, glm::vec3(0.1f));
  return f;
}

TEST(ShownImage, PathsArePngPfmOrAFolder) {
  EXPECT_TRUE(shown_path_ok("a.png"));
  EXPECT_TRUE(shown_path_ok("dir/b.PFM"));
  EXPECT_TRUE(shown_path_ok("shots/"));
  EXPECT_FALSE(shown_path_ok("a.jpg"));
  EXPECT_FALSE(shown_path_ok("pfm"));
}

TEST(ShownImage, PfmHoldsTheLinearFrameAsItIs) {
  ScratchFolder dir;
  ViewSettings view;
  Scene scene = test::two_sphere_scene();
  scene.render.exposure = 3.0f;  // a display setting: not in the linear file
  const RenderedFrame f = frame_3x2();
  write_shown(dir.file("shown.pfm"), f, scene, view, false);
  const Image back = read_pfm(dir.file("shown.pfm"));
  ASSERT_EQ(back.width, 3);
  ASSERT_EQ(back.height, 2);
  for (int i = 0; i < 6; ++i) EXPECT_EQ(back.pixels[i], f.images.total.pixels[i]) << i;
  view.mode = ViewMode::single;  // one term shown: that term
  view.single = TermView::diffuse;
  write_shown(dir.file("diffuse.pfm"), f, scene, view, false);
  EXPECT_EQ(read_pfm(dir.file("diffuse.pfm")).pixels[4], glm::vec3(0.1f));
}

TEST(ShownImage, PngIsTheDisplayedFrameWithTheSceneAtItsSize) {
  ScratchFolder dir;
  ViewSettings view;
  const RenderedFrame f = frame_3x2();
  Scene scene = test::two_sphere_scene();
  scene.render.exposure = 1.0f;  // x2, tone curve none (the default)
  scene.render.srgb = false;     // classic clamp: value x 255, rounded
  write_shown(dir.file("shown.png"), f, scene, view, false);
  const Png8 png = read_png(dir.file("shown.png"));
  ASSERT_EQ(png.width, 3);
  ASSERT_EQ(png.height, 2);
  // Pixel 1: (0.05, 0.25, 2) x 2 = (0.1, 0.5, 4): 25.5 -> 26, 127.5 -> 128, clamped 255.
  EXPECT_EQ(png.rgb[3], 26);
  EXPECT_EQ(png.rgb[4], 128);
  EXPECT_EQ(png.rgb[5], 255);
  const Scene back = load_scene_from_png(dir.file("shown.png"));
  EXPECT_EQ(back.render.width, 3);
  EXPECT_EQ(back.render.height, 2);
  EXPECT_EQ(back.render.spp, scene.render.spp);
  std::string settings;
  for (const auto& [keyword, text] : png.text)
    if (keyword == "gloss:settings") settings = text;
  EXPECT_NE(settings.find("kind=shown"), std::string::npos) << settings;
  EXPECT_NE(settings.find("size=3x2"), std::string::npos) << settings;
  EXPECT_NE(settings.find("shown_spp=16 converged=yes"), std::string::npos) << settings;
  EXPECT_NE(settings.find("renderer=cpu"), std::string::npos) << settings;
}

TEST(ShownImage, NoFrameIsAnError) {
  ScratchFolder dir;
  EXPECT_THROW(write_shown(dir.file("x.png"), RenderedFrame{}, test::two_sphere_scene(),
                           ViewSettings{}, false),
               std::runtime_error);
  EXPECT_FALSE(std::filesystem::exists(dir.file("x.png")));
}

}  // namespace
}  // namespace gloss
