// The environment on the raster path and in Export GLSL, through EGL: with shadows off both agree
// with the ray tracer's fast path (the same prefiltered levels, lookups and blend) within 1e-3 on
// at least 99.5 % of the pixels, every term, the sky included; planted errors (the map turned
// the wrong way, levels not blended) fail.
#include <gtest/gtest.h>

#include <cstdio>
#include <functional>
#include <string>

#include "editor/gl/egl_context.h"
#include "editor/gl/gl_texture.h"
#include "editor/gl/glsl_harness.h"
#include "editor/gl/planted_shaders.h"
#include "editor/gl/raster/raster_renderer.h"
#include "editor/model/export/environment_atlas.h"
#include "editor/model/export/glsl_export.h"
#include "engine/renderer.h"
#include "io/scene/environment_reader.h"
#include "io/scene/scene_loader.h"

namespace gloss {
namespace {

Scene environment_scene(ShadingModel model, float rotation) {
  Scene scene = load_scene(std::string(GLOSS_SCENES_DIR) + "/studio-metals.json");
  scene.render.width = 160;
  scene.render.height = 120;
  scene.render.spp = 1;
  scene.render.shadows = false;
  scene.render.env_samples = 0;  // the fast path
  scene.render.model = model;
  scene.environment.rotation = rotation;
  scene.materials[0].shininess = 20.0f;  // gold: between two levels
  return scene;
}

class RasterEnvironment : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!m_context.ok()) GTEST_SKIP() << "no EGL surfaceless GL: " << m_context.error();
  }
  test::EglContext m_context;
};

// Share of pixels within 1e-3 of the fast path, the worst term.
double agreement(const TermImages& fast, const std::function<glm::vec3(int, std::size_t)>& at,
                 const std::string& label, bool hits_only) {
  const Image* terms[test::kGlslTerms] = {&fast.total, &fast.emissive, &fast.ambient, &fast.diffuse,
                                          &fast.specular};
  double worst = 1.0;
  for (int t = 0; t < test::kGlslTerms; ++t) {
    std::size_t within = 0, counted = 0;
    double largest = 0.0;
    for (std::size_t i = 0; i < fast.total.pixels.size(); ++i) {
      if (hits_only && fast.diffuse.pixels[i] == glm::vec3(0.0f)) continue;
      ++counted;
      const glm::vec3 d = glm::abs(at(t, i) - terms[t]->pixels[i]);
      const double off = std::max(d.x, std::max(d.y, d.z));
      largest = std::max(largest, off);
      within += off <= 1e-3 ? 1 : 0;
    }
    const double share = counted == 0 ? 1.0 : double(within) / double(counted);
    std::printf("[raster-env] %s %s: %.3f%% within 1e-3 of the fast path, largest %.3g\n",
                label.c_str(), test::kGlslTermNames[t], 100.0 * share, largest);
    worst = std::min(worst, share);
  }
  return worst;
}

double raster_agreement(RasterRenderer& renderer, const Scene& scene, const std::string& label) {
  const std::shared_ptr<RenderedFrame> frame = renderer.render(scene, RasterSettings{}, true);
  const TermImages fast = render(scene);
  const Image* images[test::kGlslTerms] = {&frame->images.total, &frame->images.emissive,
                                           &frame->images.ambient, &frame->images.diffuse,
                                           &frame->images.specular};
  return agreement(
      fast, [&](int t, std::size_t i) { return images[t]->pixels[i]; }, label, false);
}

TEST_F(RasterEnvironment, AgreesWithTheFastPathWithoutShadows) {
  RasterRenderer renderer;
  for (ShadingModel model : {ShadingModel::phong, ShadingModel::blinn_phong}) {
    for (float rotation : {0.0f, 73.0f}) {
      const Scene scene = environment_scene(model, rotation);
      const std::string label =
          std::string(to_string(model)) + " rotation " + std::to_string(rotation);
      EXPECT_GE(raster_agreement(renderer, scene, label), 0.995) << label;
    }
  }
}

TEST_F(RasterEnvironment, ExportedShaderCarriesTheEnvironment) {
  Scene scene = environment_scene(ShadingModel::phong, 40.0f);
  scene.environment.as_background = false;
  PrefilterSettings settings;
  settings.texels_per_lobe = scene.render.env_resolution;
  const EnvironmentAtlas atlas =
      make_environment_atlas(*prefiltered_environment(scene.environment.map, settings));
  GlTexture texture;
  texture.set_nearest(true);
  texture.upload(atlas.image);
  std::string log;
  const std::vector<std::vector<float>> images = test::render_exported(
      scene, [&](int material) { return export_glsl(scene, material, "studio-environment.pfm"); },
      log,
      [&](GLuint program) {
        glActiveTexture(GL_TEXTURE1);
        glBindTexture(GL_TEXTURE_2D, texture.id());
        glActiveTexture(GL_TEXTURE0);
        glUniform1i(glGetUniformLocation(program, "gloss_env_atlas"), 1);
      });
  ASSERT_TRUE(log.empty()) << log;
  ASSERT_EQ(images.size(), std::size_t(test::kGlslTerms));
  const TermImages fast = render(scene);
  const double share = agreement(
      fast,
      [&](int t, std::size_t i) {
        return glm::vec3(images[t][4 * i], images[t][4 * i + 1], images[t][4 * i + 2]);
      },
      "export", true);
  EXPECT_GE(share, 0.995);
  // The shader names its atlas file and says what it leaves out.
  const std::string text = export_glsl(scene, 0, "studio-environment.pfm");
  EXPECT_NE(text.find("#define GLOSS_ENVIRONMENT 1"), std::string::npos);
  EXPECT_NE(text.find("studio-environment.pfm"), std::string::npos);
  EXPECT_NE(text.find("No horizon, no"), std::string::npos);
}

using test::with_planted_error;

TEST_F(RasterEnvironment, PlantedErrorsFail) {
  const Scene scene = environment_scene(ShadingModel::phong, 73.0f);
  // The map turned the wrong way.
  with_planted_error(
      "return vec3(w.x * r.x - w.z * r.y, w.y, w.x * r.y + w.z * r.x);",
      "return vec3(w.x * r.x + w.z * r.y, w.y, -w.x * r.y + w.z * r.x);",
      [&](RasterRenderer& r) { EXPECT_LT(raster_agreement(r, scene, "planted turn"), 0.9); });
  // The levels around alpha not blended (the lower one only).
  with_planted_error("wb = a == last ? 0.0 : k - floor(k);", "wb = 0.0;", [&](RasterRenderer& r) {
    EXPECT_LT(raster_agreement(r, scene, "planted blend"), 0.99);
  });
}

}  // namespace
}  // namespace gloss
