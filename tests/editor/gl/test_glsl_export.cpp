// Export GLSL (editor/model/export/glsl_export.h) run through GL 3.3 core without a display: the
// exported fragment shader, fed exact hit points and normals per pixel (glsl_harness.h),
// against the double-precision reference renderer of the same scene at one sample per pixel.
// docs/spec/shading.md ("A raster (GLSL) path", issue 12): with shadows off, at least 99.5 % of
// pixels within 1e-3 on every term. A planted shader error must fail the same check.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <EGL/egl.h>
#include <glad/gl.h>
#include <glm/geometric.hpp>

#include "editor/gl/egl_context.h"
#include "editor/gl/glsl_harness.h"
#include "editor/model/export/glsl_export.h"
#include "support/scene_fixtures.h"

namespace gloss {
namespace {

using test::Agreement;
using test::compile_shader;
using test::kGlslTermNames;
using test::kGlslTerms;
using test::measure_agreement;
using test::render_exported;

// The scene of the test: the fixtures' head-on sphere (attenuated light with La) plus a second,
// coloured light from the left with its own attenuation; shadows off.
Scene agreement_scene(ShadingModel model, bool energy, float alpha) {
  Scene scene = test::head_on_sphere_scene();
  PointLight second = test::make_light({-4.0f, 1.0f, 3.0f}, {0.3f, 0.6f, 0.9f}, {0.7f, 0.7f, 0.2f});
  second.ambient = {0.05f, 0.0f, 0.02f};
  second.attenuation = {0.5f, 0.0f, 0.04f};
  scene.lights.push_back(second);
  scene.materials[0].shininess = alpha;
  scene.render.model = model;
  scene.render.energy_normalize = energy;
  scene.render.shadows = false;
  scene.render.width = 160;
  scene.render.height = 120;
  scene.render.spp = 1;
  return scene;
}

// A flat quad in the plane z = 0 wound so that its normal points away from the eye (-z), lit by
// the same two lights from the eye's side: only the two-sided rule makes it lit.
Scene back_quad_scene() {
  Scene scene = agreement_scene(ShadingModel::phong, false, 30.0f);
  scene.objects.clear();
  test::add_quad(scene, {-1.3f, -1.1f, 0.0f}, {-1.3f, 1.1f, 0.0f}, {1.3f, 1.1f, 0.0f},
                 {1.3f, -1.1f, 0.0f}, 0);
  return scene;
}

// How the export of scene's material 0 (or source, when given) agrees with the reference.
Agreement measure(const Scene& scene, const std::string& source, std::string& log) {
  return measure_agreement(
      scene, [&](int) { return source; }, 1e-3, log);
}

struct Case {
  const char* name;
  ShadingModel model;
  bool energy;
  float alpha;
};

class GlslExport : public ::testing::TestWithParam<Case> {
 protected:
  void SetUp() override {
    if (!m_context.ok()) GTEST_SKIP() << "no EGL surfaceless GL: " << m_context.error();
  }
  test::EglContext m_context;
};

TEST_P(GlslExport, AgreesWithTheReferenceOnEveryTerm) {
  const Case c = GetParam();
  const Scene scene = agreement_scene(c.model, c.energy, c.alpha);
  std::string log;
  const Agreement a = measure(scene, export_glsl(scene, 0), log);
  ASSERT_TRUE(log.empty()) << log;
  for (int i = 0; i < kGlslTerms; ++i) {
    std::printf("[glsl-agreement] %s %s: %.4f%% within 1e-3, largest difference %.3g\n", c.name,
                kGlslTermNames[i], 100.0 * a.share[i], a.largest[i]);
    EXPECT_GE(a.share[i], 0.995) << kGlslTermNames[i];
  }
}

// Single cases that need a GL context: no lights, the back-facing quad, GLSL ES.
class GlslExportCases : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!m_context.ok()) GTEST_SKIP() << "no EGL surfaceless GL: " << m_context.error();
  }
  test::EglContext m_context;
};

INSTANTIATE_TEST_SUITE_P(
    Scenes, GlslExport,
    ::testing::Values(Case{"phong_alpha10", ShadingModel::phong, false, 10.0f},
                      Case{"blinn_energy_alpha200", ShadingModel::blinn_phong, true, 200.0f},
                      Case{"phong_alpha0", ShadingModel::phong, false, 0.0f},
                      Case{"phong_alpha1000", ShadingModel::phong, false, 1000.0f},
                      Case{"blinn_alpha1e6", ShadingModel::blinn_phong, false, 1e6f}),
    [](const ::testing::TestParamInfo<Case>& info) { return std::string(info.param.name); });

// The two-sided rule: a quad whose normal faces away from the eye is shaded on its visible side.
TEST_F(GlslExportCases, BackFacingQuadAgreesThroughTheTwoSidedRule) {
  const Scene scene = back_quad_scene();
  ASSERT_LT(glm::dot(glm::cross(scene.objects[0].params.quad[1] - scene.objects[0].params.quad[0],
                                scene.objects[0].params.quad[2] - scene.objects[0].params.quad[0]),
                     scene.camera.eye),
            0.0f)
      << "the quad's winding must face away from the eye";
  std::string log;
  const Agreement a = measure(scene, export_glsl(scene, 0), log);
  ASSERT_TRUE(log.empty()) << log;
  for (int i = 0; i < kGlslTerms; ++i) {
    std::printf("[glsl-agreement] back_quad %s: %.4f%% within 1e-3, largest difference %.3g\n",
                kGlslTermNames[i], 100.0 * a.share[i], a.largest[i]);
    EXPECT_GE(a.share[i], 0.995) << kGlslTermNames[i];
  }
}

// Without lights the shader still compiles (no zero-size arrays) and gives ke + ka A_scene.
TEST_F(GlslExportCases, CompilesAndGivesEmissivePlusAmbient) {
  Scene scene = agreement_scene(ShadingModel::phong, false, 10.0f);
  scene.lights.clear();
  std::string log;
  const Agreement a = measure(scene, export_glsl(scene, 0), log);
  ASSERT_TRUE(log.empty()) << log;
  for (int i = 0; i < kGlslTerms; ++i) EXPECT_GE(a.share[i], 0.995) << kGlslTermNames[i];
  const std::vector<std::vector<float>> gl = render_exported(
      scene, [&](int m) { return export_glsl(scene, m); }, log);
  ASSERT_FALSE(gl.empty());
  // The centre pixel (80, 60) is on the sphere: (0.01, 0, 0) + (0.1, 0.2, 0.3) * 0.2, by hand.
  const std::size_t centre = 4 * (60 * 160 + 80);
  EXPECT_NEAR(gl[0][centre + 0], 0.03, 1e-6);
  EXPECT_NEAR(gl[0][centre + 1], 0.04, 1e-6);
  EXPECT_NEAR(gl[0][centre + 2], 0.06, 1e-6);
}

// GLSL ES 3.00 (WebGL 2's language): the export with only its version line changed compiles in
// an OpenGL ES 3 context, as its header promises. glad's entry points, loaded for the GL context,
// are Mesa's dispatch stubs and serve whichever context is current.
TEST_F(GlslExportCases, CompilesAsGlslEs300WithOnlyTheVersionLineChanged) {
  EGLDisplay display = eglGetCurrentDisplay();
  EGLContext gl_context = eglGetCurrentContext();
  const EGLint config_attributes[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
                                      EGL_OPENGL_ES3_BIT, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint count = 0;
  if (!eglBindAPI(EGL_OPENGL_ES_API) ||
      !eglChooseConfig(display, config_attributes, &config, 1, &count) || count < 1) {
    eglBindAPI(EGL_OPENGL_API);
    GTEST_SKIP() << "no EGL config for OpenGL ES 3";
  }
  const EGLint context_attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 0,
                                       EGL_NONE};
  EGLContext es = eglCreateContext(display, config, EGL_NO_CONTEXT, context_attributes);
  ASSERT_NE(es, EGL_NO_CONTEXT);
  ASSERT_TRUE(eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, es));
  EXPECT_EQ(
      std::string(reinterpret_cast<const char*>(glGetString(GL_VERSION))).rfind("OpenGL ES", 0),
      0u);
  for (const bool with_lights : {true, false}) {
    Scene scene = agreement_scene(ShadingModel::blinn_phong, true, 20.0f);
    if (!with_lights) scene.lights.clear();
    std::string source = export_glsl(scene, 0);
    const std::string core = "#version 330 core\n";
    ASSERT_EQ(source.rfind(core, 0), 0u);
    source.replace(0, core.size(), "#version 300 es\n");
    std::string log;
    const GLuint shader = compile_shader(GL_FRAGMENT_SHADER, source, log);
    EXPECT_TRUE(log.empty()) << (with_lights ? "with lights: " : "without lights: ") << log;
    glDeleteShader(shader);
    // The check can fail: ES fragment shaders have no default float precision, so the same
    // source without the export's precision line must not compile.
    const std::string precision = "precision highp float;\n";
    const std::size_t at = source.find(precision);
    ASSERT_NE(at, std::string::npos);
    source.erase(at, precision.size());
    std::string planted_log;
    glDeleteShader(compile_shader(GL_FRAGMENT_SHADER, source, planted_log));
    EXPECT_FALSE(planted_log.empty()) << "an ES shader without float precision compiled";
  }
  eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, gl_context);
  eglDestroyContext(display, es);
  eglBindAPI(EGL_OPENGL_API);
}

// Planted errors in a copy of the exported source: each must break the 99.5 % agreement on the
// total, or the check above could not fail.
struct Plant {
  const char* name;
  const char* from;
  const char* to;
  bool back_quad = false;  // the back-facing quad instead of the head-on sphere
};

class GlslPlantedError : public ::testing::TestWithParam<Plant> {
 protected:
  void SetUp() override {
    if (!m_context.ok()) GTEST_SKIP() << "no EGL surfaceless GL: " << m_context.error();
  }
  test::EglContext m_context;
};

TEST_P(GlslPlantedError, FailsTheAgreementCheck) {
  const Plant plant = GetParam();
  const Scene scene =
      plant.back_quad ? back_quad_scene() : agreement_scene(ShadingModel::phong, false, 10.0f);
  std::string source = export_glsl(scene, 0);
  const std::size_t at = source.find(plant.from);
  ASSERT_NE(at, std::string::npos) << "the exported shader no longer contains " << plant.from;
  source.replace(at, std::string(plant.from).size(), plant.to);
  std::string log;
  const Agreement a = measure(scene, source, log);
  ASSERT_TRUE(log.empty()) << log;
  std::printf("[glsl-planted] %s: total %.4f%% within 1e-3, largest difference %.3g\n", plant.name,
              100.0 * a.share[0], a.largest[0]);
  EXPECT_LT(a.share[0], 0.995) << "the planted error went unnoticed";
}

INSTANTIATE_TEST_SUITE_P(
    Errors, GlslPlantedError,
    ::testing::Values(
        Plant{"blinn_cosine_for_phong", "float c = gloss_model_cosine(f, gloss_model);",
              "float c = f.cos_blinn;"},
        Plant{"attenuation_dropped",
              "float att = gloss_attenuation(gloss_light_attenuation[i], d);", "float att = 1.0;"},
        Plant{"ambient_light_sum_dropped", "ambient_light += gloss_light_ambient[i];", ""},
        Plant{"two_sided_rule_dropped", "gloss_two_sided(n_g, n, v);", "", true},
        // pow of a negative cosine is undefined in GLSL (non-finite on llvmpipe): counted as
        // failing.
        Plant{"negative_cosine_rule_dropped", "if (!(c > 0.0)) return 0.0;", ""}),
    [](const ::testing::TestParamInfo<Plant>& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace gloss
