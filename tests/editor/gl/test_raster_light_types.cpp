// Directional and spot lights on the raster path and in Export GLSL, through EGL: shadows off,
// 99.5 % of pixels within 1e-3 of render_reference<double> on every term, differences only on
// silhouettes and hard cone edges; with shadow maps (a directional light's orthographic map, a
// spot's perspective map, a 90-degree spot's cube) the differences lie by shadow edges. Planted
// errors in the cone and the light's way must fail.
#include <gtest/gtest.h>

#include <cstdio>
#include <functional>
#include <string>

#include "editor/gl/egl_context.h"
#include "editor/gl/glsl_harness.h"
#include "editor/gl/planted_shaders.h"
#include "editor/gl/raster/raster_renderer.h"
#include "editor/model/export/glsl_export.h"
#include "io/scene/scene_loader.h"

namespace gloss {
namespace {

// The shapes of test_raster_scenes.cpp's own scenes under the new light types: a directional
// light, a smooth spot with an exponent, a hard narrow spot, a wide spot and a dim headlight.
Scene typed_scene(bool shadows, const std::string& extra_light = "") {
  const std::string text = R"({"camera": {"eye": [0.5, 2, 6], "target": [0, -0.3, 0], "fov_y": 45},
    "background": [0.1, 0.2, 0.3], "ambient": [0.05, 0.05, 0.05],
    "lights": [
      {"type": "directional", "direction": [0.4, -1, -0.3], "diffuse": [0.5, 0.45, 0.4],
       "specular": [0.6, 0.6, 0.6]},
      {"type": "spot", "position": [2, 3, 2], "direction": [-2, -3.5, -2], "cutoff": 25,
       "inner": 12, "exponent": 8, "diffuse": [0.9, 0.6, 0.3], "specular": [1, 1, 1],
       "attenuation": [1, 0.05, 0.01]},
      {"type": "spot", "position": [-2, 2.5, 1], "direction": [1, -1.5, -0.5], "cutoff": 70,
       "inner": 40, "diffuse": [0.2, 0.4, 0.8], "specular": [0.3, 0.3, 0.6]},
      {"type": "directional", "follow_camera": true, "direction": [0, 0, -1],
       "diffuse": [0.15, 0.15, 0.15], "specular": [0.1, 0.1, 0.1]})" +
                           extra_light + R"(],
    "materials": {"shiny": {"ambient": [0.2, 0.1, 0.1], "diffuse": [0.6, 0.3, 0.2],
                            "specular": [0.9, 0.9, 0.9], "shininess": 64},
                  "floor": {"preset": "jade"}},
    "objects": [
      {"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "shiny"},
      {"type": "sphere", "center": [1.6, 0.3, -1], "radius": 0.5, "material": "floor"},
      {"type": "quad", "vertices": [[-4, -1, -4], [4, -1, -4], [4, -1, 4], [-4, -1, 4]],
       "material": "floor"},
      {"type": "box", "min": [-0.4, -0.4, -0.4], "max": [0.4, 0.4, 0.4],
       "position": [-1.8, -0.6, 0.5], "rotate_y": 30, "material": "shiny"}],
    "render": {"width": 160, "height": 120, "spp": 1}})";
  Scene scene = parse_scene(text, "raster-light-types.json");
  scene.render.shadows = shadows;
  return scene;
}

// A narrow hard-edged spot (its edge counted like a shadow edge).
const char* const kHardSpot = R"(,
      {"type": "spot", "position": [0.5, 4, 1], "direction": [0, -1, -0.2], "cutoff": 9,
       "diffuse": [0.7, 0.7, 0.7], "specular": [0.5, 0.5, 0.5]})";

const Image& term(const TermImages& images, int t) {
  const Image* all[test::kGlslTerms] = {&images.total, &images.emissive, &images.ambient,
                                        &images.diffuse, &images.specular};
  return *all[t];
}

class RasterLightTypes : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!m_context.ok()) GTEST_SKIP() << "no EGL surfaceless GL: " << m_context.error();
  }
  test::EglContext m_context;
};

test::Agreement raster_agreement(RasterRenderer& renderer, const Scene& scene,
                                 const std::string& label, ShadingFrequency f) {
  RasterSettings settings;
  settings.shading = f;
  const std::shared_ptr<RenderedFrame> frame = renderer.render(scene, settings, true);
  ReferenceOptions options;
  options.gouraud = f == ShadingFrequency::vertex;
  const test::Agreement a = test::compare_with_reference(
      scene, [&](int t, std::size_t i) { return term(frame->images, t).pixels[i]; }, 1e-3, options);
  for (int t = 0; t < test::kGlslTerms; ++t) {
    std::printf("[raster-lights] %s %s: %.3f%% within 1e-3, largest %.3g, %d off the edges\n",
                label.c_str(), test::kGlslTermNames[t], 100.0 * a.share[t], a.largest[t],
                a.off_edge[t]);
  }
  return a;
}

bool agrees(const test::Agreement& a, int off_edge_allowed) {
  for (int t = 0; t < test::kGlslTerms; ++t) {
    if (a.share[t] < 0.995 || a.off_edge[t] > off_edge_allowed) return false;
  }
  return true;
}

TEST_F(RasterLightTypes, AgreeWithTheReferenceWithoutShadows) {
  RasterRenderer renderer;
  for (bool hard : {false, true}) {
    const Scene scene = typed_scene(false, hard ? kHardSpot : "");
    for (ShadingFrequency f : {ShadingFrequency::pixel, ShadingFrequency::vertex}) {
      const std::string label = std::string(hard ? "with a hard spot" : "smooth") +
                                (f == ShadingFrequency::pixel ? " per pixel" : " per vertex");
      EXPECT_TRUE(agrees(raster_agreement(renderer, scene, label, f), 1)) << label;
    }
  }
}

TEST_F(RasterLightTypes, ExportedShaderAgreesWithTheReference) {
  const Scene scene = typed_scene(false, kHardSpot);
  std::string log;
  const test::Agreement a = test::measure_agreement(
      scene, [&](int material) { return export_glsl(scene, material); }, 1e-3, log);
  ASSERT_TRUE(log.empty()) << log;
  for (int t = 0; t < test::kGlslTerms; ++t) {
    std::printf("[export-lights] %s: %.3f%% within 1e-3, largest %.3g\n", test::kGlslTermNames[t],
                100.0 * a.share[t], a.largest[t]);
  }
  EXPECT_TRUE(agrees(a, 1));
}

// Each light type's shadow map: differences within 2 pixels of the reference's shadow, cone and
// silhouette edges.
TEST_F(RasterLightTypes, ShadowMapDifferencesLieOnEdges) {
  RasterRenderer renderer;
  const Scene full = typed_scene(true, kHardSpot);
  // One light at a time, so each kind of map is judged alone: directional (orthographic), the
  // narrow spot (perspective), the wide spot (cube), the hard spot (perspective).
  for (std::size_t keep : {0u, 1u, 2u, 4u}) {
    Scene scene = full;
    scene.lights = {full.lights[keep]};
    RasterSettings settings;
    const std::shared_ptr<RenderedFrame> frame = renderer.render(scene, settings, true);
    std::vector<std::uint8_t> edges;
    const test::Agreement a = test::compare_with_reference(
        scene, [&](int t, std::size_t i) { return term(frame->images, t).pixels[i]; }, 1e-3, {},
        &edges);
    ReferenceOptions one;
    one.spp = 1;
    const TermImages ref = render_reference<double>(scene, one);
    const int w = scene.render.width, h = scene.render.height;
    int off = 0, near = 0;
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * w + x;
        const glm::vec3 d = glm::abs(ref.total.pixels[i] - frame->images.total.pixels[i]);
        if (!(std::max(d.x, std::max(d.y, d.z)) > 1e-3f)) continue;
        ++off;
        bool by_edge = false;
        for (int dy = -2; dy <= 2 && !by_edge; ++dy) {
          for (int dx = -2; dx <= 2 && !by_edge; ++dx) {
            const int u = x + dx, v = y + dy;
            by_edge = u >= 0 && v >= 0 && u < w && v < h &&
                      edges[static_cast<std::size_t>(v) * w + u] != 0;
          }
        }
        near += by_edge ? 1 : 0;
      }
    }
    std::printf("[raster-lights-shadow] light %zu (%s): %.3f%% within 1e-3, %d off, %d by edges\n",
                keep, to_string(scene.lights[0].type), 100.0 * a.share[0], off, near);
    EXPECT_GT(a.share[0], 0.98) << keep;
    EXPECT_GE(near, off * 98 / 100) << keep;
    // The map did shadow something: the reference has shadowed pixels for this light.
    int dark = 0;
    for (std::size_t i = 0; i < edges.size(); ++i) dark += edges[i];
    EXPECT_GT(dark, 20) << keep;
  }
}

// Each program holds only the code of the light types and shadow-map kinds its scene has
// (raster_programs.h): every mix of types, with and without shadows, still agrees with the
// reference (a type left out where a light needs it would shade that light as another type).
TEST_F(RasterLightTypes, EveryMixOfTypesAgrees) {
  RasterRenderer renderer;
  Scene full = typed_scene(false, kHardSpot);
  Light point;
  point.position = glm::vec3(-1.5f, 3.0f, 2.5f);
  point.diffuse = glm::vec3(0.5f, 0.5f, 0.4f);
  point.specular = glm::vec3(0.6f);
  full.lights.push_back(point);
  for (int types = 1; types < 8; ++types) {
    Scene scene = full;
    scene.lights.clear();
    for (const Light& light : full.lights) {
      if ((types >> static_cast<int>(light.type)) & 1) scene.lights.push_back(light);
    }
    const std::string label = "types " + std::to_string(types);
    for (ShadingFrequency f : {ShadingFrequency::pixel, ShadingFrequency::vertex}) {
      EXPECT_TRUE(agrees(raster_agreement(renderer, scene, label, f), 1)) << label;
    }
    // With shadows the maps' kinds vary too (cube, perspective, orthographic): lit pixels agree.
    scene.render.shadows = true;
    const test::Agreement a =
        raster_agreement(renderer, scene, label + " shadows", ShadingFrequency::pixel);
    EXPECT_GT(a.share[0], 0.97) << label;
  }
}

using test::with_planted_error;

TEST_F(RasterLightTypes, PlantedErrorsFail) {
  const Scene scene = typed_scene(false, kHardSpot);
  // The cone's cosine against the wrong axis: dot(l, s) for dot(-l, s).
  with_planted_error("vec3 chord = -l - s;", "vec3 chord = l - s;", [&](RasterRenderer& r) {
    EXPECT_FALSE(agrees(raster_agreement(r, scene, "planted cone", ShadingFrequency::pixel), 1));
  });
  // A directional light taken as travelling the other way.
  with_planted_error(
      "return gloss_factors_along(n, v, -gloss_light_direction[i], 1.0, vis);",
      "return gloss_factors_along(n, v, gloss_light_direction[i], 1.0, vis);",
      [&](RasterRenderer& r) {
        EXPECT_FALSE(agrees(raster_agreement(r, scene, "planted way", ShadingFrequency::pixel), 1));
      });
  // The smooth edge's clamp not squared.
  with_planted_error("spot *= e * e;", "spot *= e;", [&](RasterRenderer& r) {
    EXPECT_FALSE(agrees(raster_agreement(r, scene, "planted edge", ShadingFrequency::pixel), 1));
  });
}

}  // namespace
}  // namespace gloss
