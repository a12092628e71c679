// Export GLSL (editor/model/glsl_export.h) run through GL 3.3 core without a display: the
// exported fragment shader, fed the head-on sphere's exact hit points and normals per pixel,
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
#include <glm/vector_relational.hpp>

#include "editor/gl/egl_context.h"
#include "editor/model/glsl_export.h"
#include "reference/reference_renderer.h"
#include "scene/camera.h"
#include "support/scene_fixtures.h"

namespace gloss {
namespace {

// One point per covered pixel, at the pixel's centre, carrying that pixel's hit point and normal;
// the exported shader does the rest. Points of size 1 at pixel centres cover exactly their pixel.
const char* const kPointVertexShader = R"glsl(#version 330 core
layout(location = 0) in vec2 pixel_ndc;
layout(location = 1) in vec3 hit_position;
layout(location = 2) in vec3 hit_normal;
out vec3 gloss_position;
out vec3 gloss_normal;
void main() {
  gloss_position = hit_position;
  gloss_normal = hit_normal;
  gl_Position = vec4(pixel_ndc, 0.0, 1.0);
}
)glsl";

constexpr int kTerms = 5;  // total, emissive, ambient, diffuse, specular (the export's outputs)

GLuint compile(GLenum type, const std::string& source, std::string& log) {
  const GLuint shader = glCreateShader(type);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char buffer[4096] = {};
    glGetShaderInfoLog(shader, sizeof buffer, nullptr, buffer);
    log += buffer;
  }
  return shader;
}

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

// The host's per-pixel geometry, in double: the camera formula of scene/camera.h at each pixel
// centre, then the hit nearest the eye on objects[0], which is the head-on sphere (its exact
// normal) or a flat quad (the normal of its first triangle as wound, which may face away: the
// shader's two-sided rule has to flip it). One vertex per covered pixel: ndc.xy, p.xyz, n.xyz.
std::vector<float> host_hits(const Scene& scene) {
  const int w = scene.render.width, h = scene.render.height;
  const Object& object = scene.objects.at(0);
  const CameraBasis<double> basis = make_camera_basis<double>(scene.camera, w, h);
  std::vector<float> vertices;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const glm::dvec3 d = camera_direction<double>(basis, x + 0.5, y + 0.5, w, h);
      glm::dvec3 p, n;
      if (object.type == ObjectType::sphere) {
        const glm::dvec3 c(object.center);
        const double r = object.radius;
        const glm::dvec3 oc = basis.eye - c;
        const double b = glm::dot(oc, d), disc = b * b - (glm::dot(oc, oc) - r * r);
        if (disc < 0.0) continue;
        const double t = -b - std::sqrt(disc);
        if (t <= 0.0) continue;
        p = basis.eye + t * d;
        n = (p - c) / r;
      } else {  // a planar quad, axis-aligned corners (the test scenes')
        const Mesh& mesh = *object.mesh;
        const glm::dvec3 a(mesh.positions[mesh.triangles[0].x]),
            b(mesh.positions[mesh.triangles[0].y]), c(mesh.positions[mesh.triangles[0].z]);
        n = glm::normalize(glm::cross(b - a, c - a));
        const double denominator = glm::dot(d, n);
        if (denominator == 0.0) continue;
        const double t = glm::dot(a - basis.eye, n) / denominator;
        if (t <= 0.0) continue;
        p = basis.eye + t * d;
        glm::dvec3 lo(object.params.quad[0]), hi = lo;
        for (const glm::vec3& corner : object.params.quad) {
          lo = glm::min(lo, glm::dvec3(corner));
          hi = glm::max(hi, glm::dvec3(corner));
        }
        const double slack = 1e-9;
        if (glm::any(glm::lessThan(p, lo - slack)) || glm::any(glm::greaterThan(p, hi + slack))) {
          continue;
        }
      }
      const float row[8] = {float(2.0 * (x + 0.5) / w - 1.0),
                            float(1.0 - 2.0 * (y + 0.5) / h),
                            float(p.x),
                            float(p.y),
                            float(p.z),
                            float(n.x),
                            float(n.y),
                            float(n.z)};
      vertices.insert(vertices.end(), row, row + 8);
    }
  }
  return vertices;
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

// Renders objects[0] of scene with fragment_source at host_hits' points; returns the five images
// (total first) as RGBA floats, rows top to bottom, misses left at the background. Empty with a
// message in log when the program does not build.
std::vector<std::vector<float>> render_with_shader(const Scene& scene,
                                                   const std::string& fragment_source,
                                                   std::string& log) {
  const int w = scene.render.width, h = scene.render.height;
  const std::vector<float> vertices = host_hits(scene);

  const GLuint vs = compile(GL_VERTEX_SHADER, kPointVertexShader, log);
  const GLuint fs = compile(GL_FRAGMENT_SHADER, fragment_source, log);
  const GLuint program = glCreateProgram();
  glAttachShader(program, vs);
  glAttachShader(program, fs);
  glLinkProgram(program);
  GLint linked = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &linked);
  glDeleteShader(vs);
  glDeleteShader(fs);
  if (!linked) {
    char buffer[4096] = {};
    glGetProgramInfoLog(program, sizeof buffer, nullptr, buffer);
    log += buffer;
    glDeleteProgram(program);
    return {};
  }

  GLuint framebuffer = 0, textures[kTerms] = {};
  glGenFramebuffers(1, &framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glGenTextures(kTerms, textures);
  GLenum buffers[kTerms];
  for (int i = 0; i < kTerms; ++i) {
    glBindTexture(GL_TEXTURE_2D, textures[i]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, w, h, 0, GL_RGBA, GL_FLOAT, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    buffers[i] = GL_COLOR_ATTACHMENT0 + i;
    glFramebufferTexture2D(GL_FRAMEBUFFER, buffers[i], GL_TEXTURE_2D, textures[i], 0);
  }
  glDrawBuffers(kTerms, buffers);
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), static_cast<GLenum>(GL_FRAMEBUFFER_COMPLETE));
  glViewport(0, 0, w, h);
  // A miss: background in the total, 0 in every term (spec, first section).
  const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  const float background[4] = {scene.background.x, scene.background.y, scene.background.z, 0.0f};
  glClearBufferfv(GL_COLOR, 0, background);
  for (int i = 1; i < kTerms; ++i) glClearBufferfv(GL_COLOR, i, zero);

  GLuint vao = 0, vbo = 0;
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glGenBuffers(1, &vbo);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(float)),
               vertices.data(), GL_STATIC_DRAW);
  const GLsizei stride = 8 * sizeof(float);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, stride, nullptr);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride,
                        reinterpret_cast<const void*>(2 * sizeof(float)));
  glVertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, stride,
                        reinterpret_cast<const void*>(5 * sizeof(float)));
  for (GLuint a = 0; a < 3; ++a) glEnableVertexAttribArray(a);
  glUseProgram(program);
  const glm::vec3 eye = scene.camera.eye;
  glUniform3f(glGetUniformLocation(program, "gloss_eye"), eye.x, eye.y, eye.z);
  glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(vertices.size() / 8));

  std::vector<std::vector<float>> images(kTerms);
  std::vector<float> bottom_up(static_cast<std::size_t>(w) * h * 4);
  for (int i = 0; i < kTerms; ++i) {
    glReadBuffer(GL_COLOR_ATTACHMENT0 + i);
    glReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, bottom_up.data());
    images[i].resize(bottom_up.size());
    const std::size_t row = static_cast<std::size_t>(w) * 4;
    for (int y = 0; y < h; ++y) {
      std::copy_n(&bottom_up[(h - 1 - y) * row], row, &images[i][y * row]);
    }
  }
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  glUseProgram(0);
  glDeleteBuffers(1, &vbo);
  glDeleteVertexArrays(1, &vao);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteTextures(kTerms, textures);
  glDeleteFramebuffers(1, &framebuffer);
  glDeleteProgram(program);
  return images;
}

// Share of pixels whose largest channel difference to reference is within tolerance.
double share_within(const std::vector<float>& gl, const Image& reference, double tolerance,
                    double* largest = nullptr) {
  std::size_t good = 0;
  double worst = 0.0;
  for (std::size_t i = 0; i < reference.pixels.size(); ++i) {
    const glm::vec3 ref = reference.pixels[i];
    double e = 0.0;
    for (int k = 0; k < 3; ++k) e = std::max(e, std::abs(double(gl[4 * i + k]) - double(ref[k])));
    worst = std::max(worst, e);
    if (e <= tolerance) ++good;
  }
  if (largest != nullptr) *largest = worst;
  return double(good) / double(reference.pixels.size());
}

struct Agreement {
  double share[kTerms] = {};    // within 1e-3, total first
  double largest[kTerms] = {};  // largest channel difference
};

Agreement measure(const Scene& scene, const std::string& fragment_source, std::string& log) {
  Agreement a;
  const std::vector<std::vector<float>> gl = render_with_shader(scene, fragment_source, log);
  if (gl.empty()) return a;
  ReferenceOptions options;
  options.spp = 1;
  const TermImages ref = render_reference<double>(scene, options);
  const Image* images[kTerms] = {&ref.total, &ref.emissive, &ref.ambient, &ref.diffuse,
                                 &ref.specular};
  for (int i = 0; i < kTerms; ++i)
    a.share[i] = share_within(gl[i], *images[i], 1e-3, &a.largest[i]);
  return a;
}

const char* const kTermNames[kTerms] = {"total", "emissive", "ambient", "diffuse", "specular"};

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
  for (int i = 0; i < kTerms; ++i) {
    std::printf("[glsl-agreement] %s %s: %.4f%% within 1e-3, largest difference %.3g\n", c.name,
                kTermNames[i], 100.0 * a.share[i], a.largest[i]);
    EXPECT_GE(a.share[i], 0.995) << kTermNames[i];
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
                      Case{"phong_alpha0", ShadingModel::phong, false, 0.0f}),
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
  for (int i = 0; i < kTerms; ++i) {
    std::printf("[glsl-agreement] back_quad %s: %.4f%% within 1e-3, largest difference %.3g\n",
                kTermNames[i], 100.0 * a.share[i], a.largest[i]);
    EXPECT_GE(a.share[i], 0.995) << kTermNames[i];
  }
}

// Without lights the shader still compiles (no zero-size arrays) and gives ke + ka A_scene.
TEST_F(GlslExportCases, CompilesAndGivesEmissivePlusAmbient) {
  Scene scene = agreement_scene(ShadingModel::phong, false, 10.0f);
  scene.lights.clear();
  std::string log;
  const Agreement a = measure(scene, export_glsl(scene, 0), log);
  ASSERT_TRUE(log.empty()) << log;
  for (int i = 0; i < kTerms; ++i) EXPECT_GE(a.share[i], 0.995) << kTermNames[i];
  const std::vector<std::vector<float>> gl = render_with_shader(scene, export_glsl(scene, 0), log);
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
    const GLuint shader = compile(GL_FRAGMENT_SHADER, source, log);
    EXPECT_TRUE(log.empty()) << (with_lights ? "with lights: " : "without lights: ") << log;
    glDeleteShader(shader);
    // The check can fail: ES fragment shaders have no default float precision, so the same
    // source without the export's precision line must not compile.
    const std::string precision = "precision highp float;\n";
    const std::size_t at = source.find(precision);
    ASSERT_NE(at, std::string::npos);
    source.erase(at, precision.size());
    std::string planted_log;
    glDeleteShader(compile(GL_FRAGMENT_SHADER, source, planted_log));
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
        Plant{"attenuation_dropped", "float att = gloss_attenuation(attenuation_coeffs, d);",
              "float att = 1.0;"},
        Plant{"ambient_light_sum_dropped", "ambient_light += gloss_light_ambient[i];", ""},
        Plant{"two_sided_rule_dropped", "gloss_two_sided(n_g, n, v);", "", true}),
    [](const ::testing::TestParamInfo<Plant>& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace gloss
