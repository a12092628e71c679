// The raster path (editor/gl/raster/raster_renderer.h) against render_reference<double> at one
// sample per pixel, through EGL (issue 12, item 4). Shadows off: at least 99.5 % of pixels within
// 1e-3 on every term, per pixel against the exact contract and per vertex against the reference's
// own Gouraud option. Shadow maps: the pixels that differ are counted and must lie on or next to
// the reference's shadow and silhouette edges. Planted shader errors must fail the same checks.
#include <gtest/gtest.h>

#include <cstdio>
#include <functional>
#include <string>

#include "editor/gl/egl_context.h"
#include "editor/gl/glsl_harness.h"
#include "editor/gl/planted_shaders.h"
#include "editor/gl/raster/raster_renderer.h"
#include "io/scene/scene_loader.h"

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
// normalisation, a shininess of 1e4, two coloured lights, no light at all, an eye inside a
// sphere's impostor cube.
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
  } else if (which == "diagonal") {  // the impostor cube's near corner before the near plane
    camera = R"({"eye": [1.5, 1.5, 1.5], "target": [0, 0, 0], "fov_y": 60})";
  } else if (which == "corner") {  // outside the sphere, inside its impostor cube: no culling
    camera = R"({"eye": [0.9, 0.7, 0.9], "target": [0, -0.2, 0], "fov_y": 70})";
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
  std::string scene_text = text;
  if (which == "ground") {  // a ground sphere of radius 1e4 under a close eye
    const std::size_t at = scene_text.find(R"({"type": "quad")");
    const std::size_t end = scene_text.find('}', at) + 1;
    scene_text.replace(at, end - at,
                       R"({"type": "sphere", "center": [0, -10001, 0], "radius": 10000,
                           "material": "floor"})");
    const std::size_t eye = scene_text.find(R"("eye": [0, 1, 6])");
    scene_text.replace(eye, 16, R"("eye": [0.3, 0.2, 1.9])");
  }
  Scene scene = parse_scene(scene_text, "raster-" + which + ".json");
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
        // The share alone would let a small object vanish: a difference must lie where a hit
        // can flip (the edge mask); 2 allowed for cornell-teapot per vertex.
        EXPECT_LE(a.off_edge[t], 2)
            << name << " " << frequency_name(f) << " " << test::kGlslTermNames[t];
      }
    }
  }
}

TEST_F(RasterAgreement, OwnScenesWithoutShadows) {
  RasterRenderer renderer;
  for (const char* which :
       {"plain", "blinn", "sharp", "dark", "behind", "close", "corner", "diagonal", "ground"}) {
    const Scene scene = own_scene(which);
    for (ShadingFrequency f : {ShadingFrequency::pixel, ShadingFrequency::vertex}) {
      const test::Agreement a = agreement(renderer, scene, f, which);
      for (int t = 0; t < test::kGlslTerms; ++t) {
        EXPECT_GE(a.share[t], 0.995)
            << which << " " << frequency_name(f) << " " << test::kGlslTermNames[t];
        // 1 in "behind": the box's bottom face lies in the floor's plane, and from below the
        // depth test and Embree may each keep a different one of the two coplanar faces.
        EXPECT_LE(a.off_edge[t], 1)
            << which << " " << frequency_name(f) << " " << test::kGlslTermNames[t];
      }
    }
  }
}

}  // namespace
}  // namespace gloss

namespace gloss {
namespace {

// Pixels of mask (width x height, 1 = edge) grown by radius pixels in every direction.
std::vector<std::uint8_t> dilate(const std::vector<std::uint8_t>& mask, int width, int height,
                                 int radius) {
  std::vector<std::uint8_t> out(mask.size(), 0);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      if (mask[static_cast<std::size_t>(y) * width + x] == 0) continue;
      for (int dy = -radius; dy <= radius; ++dy) {
        for (int dx = -radius; dx <= radius; ++dx) {
          const int u = x + dx, v = y + dy;
          if (u >= 0 && v >= 0 && u < width && v < height) {
            out[static_cast<std::size_t>(v) * width + u] = 1;
          }
        }
      }
    }
  }
  return out;
}

struct ShadowCount {
  int off = 0;         // pixels whose total is off by more than 1e-3
  int on_edge = 0;     // of those, on the reference's silhouette / shadow edge mask
  int near_edge = 0;   // of those, within 2 pixels of it
  double share = 0.0;  // pixels within 1e-3
};

ShadowCount count_shadow_differences(RasterRenderer& renderer, const Scene& scene,
                                     const RasterSettings& settings, const std::string& label) {
  const std::shared_ptr<RenderedFrame> frame = renderer.render(scene, settings, true);
  std::vector<std::uint8_t> edges;
  ReferenceOptions options;
  options.gouraud = settings.shading == ShadingFrequency::vertex;
  const test::Agreement a = test::compare_with_reference(
      scene, [&](int t, std::size_t i) { return term(frame->images, t).pixels[i]; }, kTolerance,
      options, &edges);
  // The totals again, pixel by pixel, to place each difference against the edges.
  ReferenceOptions again = options;
  again.spp = 1;
  const TermImages ref = render_reference<double>(scene, again);
  const int w = scene.render.width, h = scene.render.height;
  const std::vector<std::uint8_t> near = dilate(edges, w, h, 2);
  ShadowCount c;
  c.share = a.share[0];
  for (std::size_t i = 0; i < ref.total.pixels.size(); ++i) {
    const glm::vec3 d = glm::abs(ref.total.pixels[i] - frame->images.total.pixels[i]);
    if (!(std::max(d.x, std::max(d.y, d.z)) > kTolerance)) continue;
    ++c.off;
    c.on_edge += edges[i];
    c.near_edge += near[i];
  }
  std::printf(
      "[raster-shadow] %s map %d bias %.2g %s: %.3f%% within 1e-3; %d pixels off, %d on "
      "the edge mask, %d within 2 pixels of it\n",
      label.c_str(), settings.shadow_map_size, settings.shadow_bias,
      frequency_name(settings.shading), 100.0 * c.share, c.off, c.on_edge, c.near_edge);
  return c;
}

TEST_F(RasterAgreement, ShadowMapDifferencesLieOnShadowEdges) {
  RasterRenderer renderer;
  for (const char* name :
       {"spheres.json", "presets.json", "cornell.json", "teapot.json", "cornell-teapot.json"}) {
    const Scene scene = shipped(name, true);
    for (int size : {512, 1024, 2048}) {
      for (ShadingFrequency f : {ShadingFrequency::pixel, ShadingFrequency::vertex}) {
        RasterSettings settings;
        settings.shadow_map_size = size;
        settings.shading = f;
        const ShadowCount c = count_shadow_differences(renderer, scene, settings, name);
        // The issue asks the shadow-free 99.5 %; with shadow maps it asks where the differences
        // are. (Per vertex on the teapots, 99.2-99.6 %: Gouraud weights reach past the
        // terminator, where the map and the shadow ray disagree about self-shadowing.)
        EXPECT_GT(c.share, 0.99) << name << " map " << size;
        // A shadow map's texel decides a whole patch of pixels near an edge, so a difference
        // may sit a pixel or two beside the reference's one-pixel-wide edge, never farther.
        EXPECT_GE(c.near_edge, c.off * 98 / 100) << name << " map " << size;
      }
    }
  }
}

using test::with_planted_error;

// Whether scene's images from renderer pass the shadow-free agreement check on every term.
bool agrees(RasterRenderer& renderer, const Scene& scene, ShadingFrequency f) {
  const test::Agreement a = agreement(renderer, scene, f, "planted");
  for (int t = 0; t < test::kGlslTerms; ++t) {
    if (a.share[t] < 0.995) return false;
  }
  return true;
}

TEST_F(RasterAgreement, PlantedShaderErrorsFail) {
  const Scene scene = own_scene("plain");
  const Scene teapot = shipped("teapot.json", false);
  {
    RasterRenderer honest;  // the same checks pass without a plant
    ASSERT_TRUE(agrees(honest, scene, ShadingFrequency::pixel));
    ASSERT_TRUE(agrees(honest, teapot, ShadingFrequency::vertex));
  }
  // The exponent 1 % too large (the contract, every program).
  with_planted_error(
      "return pow(c, alpha);", "return pow(c, alpha * 1.01);",
      [&](RasterRenderer& r) { EXPECT_FALSE(agrees(r, scene, ShadingFrequency::pixel)); });
  // The second and third attenuation coefficients dropped.
  with_planted_error(
      "return 1.0 / (c.x + d * (c.y + d * c.z));", "return 1.0 / c.x;",
      [&](RasterRenderer& r) { EXPECT_FALSE(agrees(r, scene, ShadingFrequency::pixel)); });
  // The impostor's normal not of unit length.
  with_planted_error(
      "vec3 n = (p - gloss_sphere_centre) / gloss_sphere_radius;",
      "vec3 n = (p - gloss_sphere_centre) / (1.01 * gloss_sphere_radius);",
      [&](RasterRenderer& r) { EXPECT_FALSE(agrees(r, scene, ShadingFrequency::pixel)); });
  // Gouraud weights not clamped and scaled: the per-vertex path alone.
  with_planted_error("vec2 w = max(gloss_light_weights[i], vec2(0.0));",
                     "vec2 w = 1.01 * gloss_light_weights[i];", [&](RasterRenderer& r) {
                       EXPECT_TRUE(agrees(r, teapot, ShadingFrequency::pixel));
                       EXPECT_FALSE(agrees(r, teapot, ShadingFrequency::vertex));
                     });
  // Shadow maps that never shadow: the differences leave the shadow edges.
  with_planted_error(
      "return dist <= stored + bias ? 1.0 : 0.0;", "return 1.0;", [&](RasterRenderer& r) {
        const ShadowCount c =
            count_shadow_differences(r, shipped("spheres.json", true), RasterSettings{}, "planted");
        EXPECT_LT(c.near_edge, c.off * 98 / 100);
      });
}

}  // namespace
}  // namespace gloss
