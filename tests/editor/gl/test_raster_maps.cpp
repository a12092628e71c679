// Maps on the raster path (shaders/texture_lookup.glsl) against render_reference<double> at one
// sample per pixel, through EGL: the same footprint formula and bilinear weights in fp32 with
// texelFetch as the ray tracer's, so at least 99.5 % of the pixels agree within 1e-3 on every
// term, shadows off, for each kind of map. Cut-out edges, like silhouettes, are where a hit can
// flip: differing pixels there are counted, not hidden. Planted errors in the GLSL lookup (v
// not flipped, bilinear weights swapped, the handedness ignored) must fail.
#include <gtest/gtest.h>

#include <unistd.h>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "editor/gl/egl_context.h"
#include "editor/gl/glsl_harness.h"
#include "editor/gl/raster/raster_renderer.h"
#include "editor/model/export/glsl_export.h"
#include "io/image/image_io.h"
#include "reference/reference_renderer.h"
#include "scene/geometry/tangent_space.h"
#include "support/maps_scene.h"
#include "support/test_maps.h"

namespace gloss {
namespace {

const Image& term(const TermImages& images, int t) {
  const Image* all[test::kGlslTerms] = {&images.total, &images.emissive, &images.ambient,
                                        &images.diffuse, &images.specular};
  return *all[t];
}

// Two spheres, a floor quad and a box, lit by two lights; the maps of `which` on every material.
Scene mapped_scene(const std::string& which) {
  Scene scene = test::maps_scene("raster-maps-" + which + ".json");
  for (Material& m : scene.materials) {
    if (which == "diffuse" || which == "bilinear") {
      if (which == "bilinear") scene.render.map_filter = MapFilter::bilinear;
      m.map(MapSlot::diffuse) = test::map_of(test::checker(64, 8), "checker");
      m.map(MapSlot::diffuse).scale = glm::vec2(3.0f, 2.0f);
    } else if (which == "colours") {  // every colour map, wrap modes and a turned map
      test::put_colour_maps(m);
    } else if (which == "normal") {
      m.map(MapSlot::normal) = test::map_of(test::ripples(64, 0.6f), "ripples");
      m.normal_scale = 1.5f;
    } else if (which == "bump") {
      m.map(MapSlot::bump) = test::map_of(test::bumps(64), "bumps");
      m.bump_scale = 0.02f;
    } else if (which == "cutout") {
      m.map(MapSlot::opacity) = test::map_of(test::holes(64, 16), "holes");
      m.map(MapSlot::diffuse) = test::map_of(test::uv_ramp(16), "ramp");
    }
  }
  return scene;
}

struct Figures {
  double worst_share = 1.0;
  int off_edge = 0;
};

Figures agreement(RasterRenderer& renderer, const Scene& scene, const std::string& label) {
  RasterSettings settings;
  const std::shared_ptr<RenderedFrame> frame = renderer.render(scene, settings, true);
  if (const char* dir = std::getenv("GLOSS_MAPS_DEBUG")) {  // both images, to look at
    write_pfm(std::string(dir) + "/" + label + "-raster.pfm", frame->images.total);
    write_pfm(std::string(dir) + "/" + label + "-reference.pfm",
              render_reference<double>(scene).total);
  }
  const test::Agreement a = test::compare_with_reference(
      scene, [&](int t, std::size_t i) { return term(frame->images, t).pixels[i]; }, 1e-3);
  Figures f;
  for (int t = 0; t < test::kGlslTerms; ++t) {
    std::printf("[raster maps] %s %s: %.3f%% within 1e-3, largest %.3g, %d off the edge mask\n",
                label.c_str(), test::kGlslTermNames[t], 100.0 * a.share[t], a.largest[t],
                a.off_edge[t]);
    f.worst_share = std::min(f.worst_share, a.share[t]);
    f.off_edge = std::max(f.off_edge, a.off_edge[t]);
  }
  return f;
}

class RasterMaps : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!m_context.ok()) GTEST_SKIP() << "no EGL surfaceless GL: " << m_context.error();
  }
  test::EglContext m_context;
};

TEST_F(RasterMaps, EveryKindOfMapAgreesWithTheReference) {
  RasterRenderer renderer;
  for (const char* which : {"diffuse", "bilinear", "colours", "normal", "bump"}) {
    const Figures f = agreement(renderer, mapped_scene(which), which);
    EXPECT_GE(f.worst_share, 0.995) << which;
  }
}

// A cut-out's edge is a silhouette the reference's edge mask does not draw: the pixels beyond
// 1e-3 must be few (counted and printed) and the rest agree.
TEST_F(RasterMaps, CutOutsAgreeButForTheirEdges) {
  RasterRenderer renderer;
  const Figures f = agreement(renderer, mapped_scene("cutout"), "cutout");
  EXPECT_GE(f.worst_share, 0.995);
}

TEST_F(RasterMaps, PlantedLookupErrorsFail) {
  const std::pair<const char*, const char*> edits[] = {
      // v not flipped: row 0 read as the bottom.
      {"(1.0 - cv) * float(size.y) - 0.5", "cv * float(size.y) - 0.5"},
      // the bilinear weights of the two columns swapped.
      {"* (1.0 - f.x) +\n             texelFetch(s, ivec2(i1, j0), level) * f.x",
       "* f.x +\n             texelFetch(s, ivec2(i1, j0), level) * (1.0 - f.x)"},
      // the tangent frame's handedness ignored.
      {"vec3 b = w * cross(N, t);", "vec3 b = cross(N, t);"},
  };
  for (const auto& [from, to] : edits) {
    RasterRenderer planted([&](const std::string& text) {
      std::string out = text;
      const std::size_t at = out.find(from);
      if (at != std::string::npos) out.replace(at, std::string(from).size(), to);
      return out;
    });
    // The handedness shows on a mirrored map; the others on the colour maps.
    Scene scene =
        mapped_scene(std::string(to).find("cross") != std::string::npos ? "normal" : "colours");
    if (std::string(to).find("cross") != std::string::npos) {  // a floor with mirrored (u, v)
      Mesh floor = *scene.objects[2].mesh;
      for (glm::vec2& uv : floor.uv[0]) uv.x = 1.0f - uv.x;
      floor.tangents.clear();
      generate_tangents(floor);
      scene.objects[2].mesh = std::make_shared<const Mesh>(std::move(floor));
    }
    const Figures f = agreement(planted, scene, std::string("planted: ") + to);
    EXPECT_LT(f.worst_share, 0.99) << "the planted error went unnoticed: " << to;
  }
}

// Export GLSL with maps (editor/model/export/glsl_export_maps.h): the shader of a material with
// every kind of map compiles in GL 3.3 core, and the level files beside it hold the pyramid's
// levels texel for texel (level 0's top-left texel is the map's first).
TEST_F(RasterMaps, ExportedShaderWithMapsCompilesAndWritesItsLevels) {
  for (const char* which : {"colours", "normal", "bump", "cutout"}) {
    const Scene scene = mapped_scene(which);
    const std::string source = export_glsl(scene, 0, "environment.pfm", "/tmp/x/shader.glsl");
    EXPECT_NE(source.find("gloss_map_values"), std::string::npos) << which;
    std::string log;
    glDeleteShader(test::compile_shader(GL_FRAGMENT_SHADER, source, log));
    EXPECT_TRUE(log.empty()) << which << ": " << log;
  }
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("gloss-export-maps-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const Scene scene = mapped_scene("colours");
  write_glsl_export((dir / "shader.glsl").string(), scene, 0);
  const Texture& ramp = *scene.materials[0].map(MapSlot::diffuse).texture;
  for (int l = 0; l < ramp.level_count(); ++l) {
    const Image level =
        read_pfm((dir / ("shader-diffuse_map-L" + std::to_string(l) + ".pfm")).string());
    ASSERT_EQ(level.width, ramp.levels[static_cast<std::size_t>(l)].width);
    ASSERT_EQ(level.height, ramp.levels[static_cast<std::size_t>(l)].height);
    EXPECT_EQ(level.at(0, 0).x, ramp.levels[static_cast<std::size_t>(l)].texels[0]);
  }
  EXPECT_TRUE(std::filesystem::exists(dir / "shader-emission_map-L0.pfm"));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace gloss
