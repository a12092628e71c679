// The UV checker view (docs/editor.md, "View & Quality panel"): a view setting that hands the
// renderers the document with the checker material on every object, never an edit of the
// document; what a render of it shows, worked out from the checker's rules (texture/uv_checker.h).
#include <gtest/gtest.h>

#include "base/error.h"
#include "editor/model/export/export_image.h"
#include "editor/model/script/script.h"
#include "editor/model/script/script_runner.h"
#include "support/quiet_script_host.h"
#include "support/scene_fixtures.h"
#include "support/test_scene.h"
#include "texture/uv_checker.h"

namespace gloss {
namespace {

TEST(UvCheckerView, SwapsEveryMaterialAndLeavesTheDocument) {
  const Scene document = test::two_sphere_scene();
  ViewSettings view;
  const Scene off = scene_as_viewed(document, view);
  EXPECT_TRUE(off.materials == document.materials);
  view.uv_checker = true;
  const Scene on = scene_as_viewed(document, view);
  ASSERT_EQ(on.materials.size(), 2u);
  for (const Material& m : on.materials) {
    EXPECT_EQ(m.diffuse, glm::vec3(1.0f));
    EXPECT_EQ(m.specular, glm::vec3(0.0f));
    EXPECT_EQ(m.emission, glm::vec3(0.0f));
    EXPECT_EQ(m.map(MapSlot::diffuse).texture, shared_uv_checker());
    for (MapSlot other : {MapSlot::ambient, MapSlot::specular, MapSlot::emission,
                          MapSlot::shininess, MapSlot::opacity, MapSlot::normal, MapSlot::bump}) {
      EXPECT_FALSE(m.has_map(other));
    }
  }
  EXPECT_EQ(on.material_names, document.material_names);
  EXPECT_EQ(document.materials[0].diffuse, glm::vec3(0.6f, 0.1f, 0.1f));  // untouched
}

// A 2 x 2 quad facing the camera 5 units away, (u, v) = ((x + 1) / 2, (y + 1) / 2) by the
// contract's corner order, lit by the ambient alone (A = 1): a pixel is ka 0.15 times the
// checker there.
Scene facing_quad() {
  Scene scene;
  scene.camera.eye = {0.0f, 0.0f, 5.0f};
  scene.camera.target = {0.0f, 0.0f, 0.0f};
  scene.camera.fov_y = 40.0f;
  scene.ambient = glm::vec3(1.0f);
  scene.materials = {Material{}};
  scene.material_names = {"grey"};
  test::add_quad(scene, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, 0);
  scene.render.width = scene.render.height = 128;
  scene.render.spp = 1;
  return scene;
}

// The pixel that sees the quad's point (x, y): the plane is 5 units away, tan 20 deg = 0.36397.
glm::vec3 pixel_at(const Image& image, float x, float y) {
  const float half = 5.0f * 0.36397f;
  const int col = static_cast<int>((x / half + 1.0f) * 0.5f * image.width);
  const int row = static_cast<int>((1.0f - y / half) * 0.5f * image.height);
  return image.at(col, row);
}

TEST(UvCheckerView, ARenderShowsHueAlongUAndBrightnessAlongV) {
  const Scene document = facing_quad();
  ViewSettings view;
  view.uv_checker = true;
  const Image image = render_export(document, view, ScreenshotKind::exr);  // linear
  // The middle of cell (1, 1), u = v = 0.1875, world (-0.625, -0.625): hue 45 degrees, so
  // green / red = 0.75 and no blue (the cell's grid lines, 2 texels of 64 at 0.02, are within
  // the tolerance); brightness 0.15 (0.2 + 0.8 / 7) = 0.0471.
  const glm::vec3 a = pixel_at(image, -0.625f, -0.625f);
  EXPECT_NEAR(a.g / a.r, 0.75f, 0.05f);
  EXPECT_LT(a.b, 0.01f * a.r + 0.002f);
  EXPECT_NEAR(a.r, 0.15f * 0.3142857f, 0.004f);
  // Cell (6, 2), u = 0.8125, v = 0.3125, world (0.625, -0.375): hue 270, red / blue = 0.5.
  const glm::vec3 b = pixel_at(image, 0.625f, -0.375f);
  EXPECT_NEAR(b.r / b.b, 0.5f, 0.05f);
  EXPECT_LT(b.g, 0.05f * b.b);
  // Cell (1, 5) above cell (1, 1): the same hue, brighter (0.2 + 4 / 7 = 0.771 against 0.314).
  const glm::vec3 c = pixel_at(image, -0.625f, 0.375f);
  EXPECT_NEAR(c.g / c.r, 0.75f, 0.05f);
  EXPECT_NEAR(c.r / a.r, 0.7714286f / 0.3142857f, 0.2f);
  // The document renders its own grey material: ka 0.2 x A everywhere on the quad.
  view.uv_checker = false;
  const Image plain = render_export(document, view, ScreenshotKind::exr);
  EXPECT_NEAR(pixel_at(plain, -0.625f, -0.625f).g, 0.2f, 1e-5f);
  // The settings chunk says the screenshot shows the checker.
  view.uv_checker = true;
  const TextChunks text = export_text(document, view, ScreenshotKind::viewport);
  bool said = false;
  for (const auto& [keyword, value] : text) {
    if (keyword == "gloss:settings") said = value.find("uv_checker=on") != std::string::npos;
  }
  EXPECT_TRUE(said);
}

TEST(UvCheckerView, TheScriptLineIsAViewSettingNotAnEdit) {
  test::QuietScriptHost host(test::two_sphere_scene());
  const std::uint64_t revision = host.layer().revision();
  const Script s = parse_script("view uv_checker on\n", "v.txt");
  testing::internal::CaptureStdout();
  run_script_line(s, s.lines[0], host);
  testing::internal::GetCapturedStdout();
  EXPECT_TRUE(host.view().uv_checker);
  EXPECT_EQ(host.layer().revision(), revision);
  EXPECT_FALSE(host.layer().can_undo());
  const Script off = parse_script("view uv_checker off\n", "v.txt");
  run_script_line(off, off.lines[0], host);
  EXPECT_FALSE(host.view().uv_checker);
  EXPECT_THROW(parse_script("view uv_checker maybe\n", "v.txt"), InputError);
}

}  // namespace
}  // namespace gloss
