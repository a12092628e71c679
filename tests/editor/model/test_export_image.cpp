// Screenshot files: timestamped names never replace a file, the term sheet's layout, exposure,
// and text chunks that reproduce the scene.
#include <gtest/gtest.h>

#include <filesystem>

#include "editor/model/export/export_image.h"
#include "editor/model/export/sheet_labels.h"
#include "io/image/image_io.h"
#include "io/scene/scene_loader.h"
#include "support/test_scene.h"

namespace gloss {
namespace {

std::filesystem::path temp_folder(const std::string& name) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("gloss-export-test-" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

TEST(ExportImage, TimestampedNamesNeverReplaceAFile) {
  const std::filesystem::path dir = temp_folder("unique");
  const std::time_t when = 1700000000;  // the same second for every write
  const Image white(4, 2, glm::vec3(1.0f)), black(4, 2, glm::vec3(0.0f));
  const std::filesystem::path a = write_png_unique(dir, "shot", white, false, {}, when);
  const std::filesystem::path b = write_png_unique(dir, "shot", black, false, {}, when);
  const std::filesystem::path c = write_png_unique(dir, "shot", black, false, {}, when);
  EXPECT_EQ(a.filename().string(), "shot-" + timestamp_text(when) + ".png");
  EXPECT_EQ(b.filename().string(), "shot-" + timestamp_text(when) + "-2.png");
  EXPECT_EQ(c.filename().string(), "shot-" + timestamp_text(when) + "-3.png");
  EXPECT_EQ(read_png(a.string()).rgb.front(), 255);  // the first file kept its pixels
  EXPECT_EQ(read_png(b.string()).rgb.front(), 0);
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    (void)entry;
    ++files;
  }
  EXPECT_EQ(files, 3u);  // no temporaries left behind
}

TEST(ExportImage, TimestampIsDateAndTime) {
  const std::string text = timestamp_text(std::time(nullptr));
  ASSERT_EQ(text.size(), 15u);  // YYYYMMDD-HHMMSS
  EXPECT_EQ(text[8], '-');
}

TEST(ExportImage, TermSheetPlacesTheFourPanesUnderTheirLabels) {
  TermImages terms;
  terms.emissive = Image(3, 2, glm::vec3(0.1f));
  terms.ambient = Image(3, 2, glm::vec3(0.05f));
  terms.diffuse = Image(3, 2, glm::vec3(0.3f));
  terms.specular = Image(3, 2, glm::vec3(0.4f));
  terms.total = Image(3, 2, glm::vec3(0.85f));
  const Image sheet = term_sheet(terms);
  const int band = term_sheet_band(2);
  EXPECT_EQ(band, 16);  // 12-pixel font at scale 1, 2 pixels above and below
  ASSERT_EQ(sheet.width, 6);
  ASSERT_EQ(sheet.height, 2 * (2 + band));
  EXPECT_NEAR(sheet.at(0, band).x, 0.15f, 1e-6f);          // emissive + ambient, top left
  EXPECT_NEAR(sheet.at(5, band + 1).y, 0.3f, 1e-6f);       // diffuse, top right
  EXPECT_NEAR(sheet.at(2, 2 * band + 2).z, 0.4f, 1e-6f);   // specular, bottom left
  EXPECT_NEAR(sheet.at(3, 2 * band + 3).x, 0.85f, 1e-6f);  // total, bottom right
}

TEST(ExportImage, TermSheetLabelsAreWhiteTextInTheStrips) {
  TermImages terms;
  for (Image* image :
       {&terms.emissive, &terms.ambient, &terms.diffuse, &terms.specular, &terms.total}) {
    *image = Image(200, 100, glm::vec3(0.25f));
  }
  terms.emissive = Image(200, 100, glm::vec3(0.0f));
  const Image sheet = term_sheet(terms);
  const int band = term_sheet_band(100);
  int white[4] = {0, 0, 0, 0};
  for (int pane = 0; pane < 4; ++pane) {
    const int ox = (pane % 2) * 200, oy = (pane / 2) * (100 + band);
    for (int y = oy; y < oy + band; ++y) {
      for (int x = ox; x < ox + 200; ++x) {
        const glm::vec3 v = sheet.at(x, y);
        if (v == glm::vec3(1.0f))
          ++white[pane];
        else
          EXPECT_EQ(v, glm::vec3(0.0f)) << "strip pixels are black or white";
      }
    }
  }
  // "emissive + ambient" is the longest name: most ink. Every strip has some.
  for (int pane = 0; pane < 4; ++pane) EXPECT_GT(white[pane], 20) << pane;
  EXPECT_GT(white[0], white[1]);
  EXPECT_GT(label_width("emissive + ambient", 1), label_width("total", 1));
  // No ink in the panes themselves: 0.25 everywhere under the strips (0.25 + 0 top left).
  EXPECT_EQ(sheet.at(100, band + 50), glm::vec3(0.25f));
}

TEST(ExportImage, ExposedIsTheTransformBeforeItsEncoding) {
  const Image image(1, 1, glm::vec3(0.2f, 0.4f, 0.8f));
  RenderSettings render;
  render.exposure = 1.0f;  // x 2; 1.6 clamps to 1
  EXPECT_EQ(exposed(image, render).at(0, 0), glm::vec3(0.4f, 0.8f, 1.0f));
  render.exposure = -2.0f;
  EXPECT_EQ(exposed(image, render).at(0, 0), glm::vec3(0.05f, 0.1f, 0.2f));
  render.exposure = 0.0f;
  render.tone = ToneCurve::reinhard;  // 0.2 / 1.2, 0.4 / 1.4, 0.8 / 1.8
  EXPECT_NEAR(exposed(image, render).at(0, 0).x, 1.0f / 6.0f, 1e-6f);
  EXPECT_NEAR(exposed(image, render).at(0, 0).z, 4.0f / 9.0f, 1e-6f);
  render.srgb = true;  // the PNG writer encodes; exposed() leaves it
  EXPECT_NEAR(exposed(image, render).at(0, 0).y, 2.0f / 7.0f, 1e-6f);
}

TEST(ExportImage, ViewportKindFollowsTheSingleTermView) {
  TermImages terms;
  terms.emissive = Image(1, 1, glm::vec3(0.1f));
  terms.ambient = Image(1, 1, glm::vec3(0.2f));
  terms.diffuse = Image(1, 1, glm::vec3(0.3f));
  terms.specular = Image(1, 1, glm::vec3(0.4f));
  terms.total = Image(1, 1, glm::vec3(1.0f));
  ViewSettings view;
  EXPECT_EQ(viewport_image(terms, view).at(0, 0).x, 1.0f);
  view.mode = ViewMode::single;
  view.single = TermView::specular;
  EXPECT_EQ(viewport_image(terms, view).at(0, 0).x, 0.4f);
  view.single = TermView::emissive_ambient;
  EXPECT_NEAR(viewport_image(terms, view).at(0, 0).x, 0.3f, 1e-6f);
}

// The raster path's screenshots go through export_image with its own frame's terms.
TEST(ExportImage, ExportImageExposesTheChosenTermOfGivenTerms) {
  TermImages terms;
  terms.emissive = Image(1, 1, glm::vec3(0.1f));
  terms.ambient = Image(1, 1, glm::vec3(0.2f));
  terms.diffuse = Image(1, 1, glm::vec3(0.3f));
  terms.specular = Image(1, 1, glm::vec3(0.25f));
  terms.total = Image(1, 1, glm::vec3(0.85f));
  ViewSettings view;
  RenderSettings render;
  render.exposure = 1.0f;  // x2, then clamped
  EXPECT_EQ(export_image(terms, view, ScreenshotKind::viewport, render).at(0, 0).x, 1.0f);
  EXPECT_EQ(export_image(terms, view, ScreenshotKind::exr, render).at(0, 0).x, 0.85f);  // linear
  view.mode = ViewMode::single;
  view.single = TermView::specular;
  EXPECT_TRUE(export_needs_terms(view, ScreenshotKind::viewport));
  EXPECT_TRUE(export_needs_terms(view, ScreenshotKind::exr));
  EXPECT_EQ(export_image(terms, view, ScreenshotKind::viewport, render).at(0, 0).x, 0.5f);
  EXPECT_EQ(export_image(terms, view, ScreenshotKind::exr, render).at(0, 0).x, 0.25f);
  view.single = TermView::total;
  EXPECT_FALSE(export_needs_terms(view, ScreenshotKind::viewport));
  EXPECT_TRUE(export_needs_terms(view, ScreenshotKind::terms));
  const Image sheet = export_image(terms, view, ScreenshotKind::terms, render);
  EXPECT_EQ(sheet.width, 2);
  EXPECT_EQ(sheet.height, 2 * (1 + term_sheet_band(1)));
}

TEST(ExportImage, ScriptPathsNameAFileOrAFolder) {
  const std::filesystem::path dir = temp_folder("paths");
  const Image image(2, 2, glm::vec3(0.5f));
  const std::string file = (dir / "named.png").string();
  EXPECT_EQ(write_export(file, image, false, {}).string(), file);
  EXPECT_EQ(write_export(file, image, false, {}).string(), file);  // a named file is replaced
  const std::filesystem::path inside = write_export(dir.string(), image, false, {});
  EXPECT_EQ(inside.parent_path(), dir);
  EXPECT_EQ(inside.filename().string().rfind("gloss-", 0), 0u);
}

TEST(ExportImage, TextChunksCarryTheScene) {
  const Scene scene = test::two_sphere_scene();
  const TextChunks text = export_text(scene, ViewSettings{}, ScreenshotKind::viewport);
  const std::filesystem::path dir = temp_folder("chunks");
  const std::string file = (dir / "chunks.png").string();
  write_png(file, Image(2, 2), false, text);
  const Png8 png = read_png(file);
  std::string scene_text, settings;
  for (const auto& [key, value] : png.text) {
    if (key == "gloss:scene") scene_text = value;
    if (key == "gloss:settings") settings = value;
  }
  EXPECT_EQ(scene_to_json_text(parse_scene(scene_text, "chunk.json")), scene_to_json_text(scene));
  EXPECT_NE(settings.find("model=phong"), std::string::npos) << settings;
  EXPECT_NE(settings.find("encoding=clamp"), std::string::npos) << settings;
  EXPECT_NE(settings.find("renderer=cpu"), std::string::npos) << settings;
}

TEST(ExportImage, RasterExportsNameTheRasterKnobs) {
  ViewSettings view;
  view.renderer = RendererChoice::gl;
  view.raster.shading = ShadingFrequency::vertex;
  view.raster.shadow_map_size = 256;
  view.raster.shadow_bias = 0.5f;
  const TextChunks text = export_text(test::two_sphere_scene(), view, ScreenshotKind::viewport);
  std::string settings;
  for (const auto& [key, value] : text) {
    if (key == "gloss:settings") settings = value;
  }
  EXPECT_NE(settings.find("renderer=gl shading=vertex shadow_map=256 shadow_bias=0.5"),
            std::string::npos)
      << settings;
}

}  // namespace
}  // namespace gloss
