// A coarse smooth mesh keeps its light up to the terminator its vertex normals give (issue 22's
// second new-user review: normal-mapped models went black in steps along the triangles past the
// faceted terminator). A convex mesh alone in the scene can shadow only itself, so with the
// shadow ray leaving from the smooth surface (shading/surface.h terminator_lift) its image with
// shadows on is its image with shadows off, on every path: the fresh render, the cached light
// move, the reference in both precisions. Without the lift (measured with it taken out of
// shadow_ray_origin), 278 of the 1608 lit pixels of 12 x 6 faces at 128 x 128 lost more than 0.02
// of their diffuse (kd 0.5) on each path.
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "engine/progressive_renderer.h"
#include "engine/renderer.h"
#include "reference/reference_renderer.h"
#include "support/scene_fixtures.h"

namespace gloss {
namespace {

using Renderer = std::function<TermImages(const Scene&)>;

// The converged frame after the light moved to its place: shadow rays from the cached hits.
TermImages render_after_light_move(const Scene& scene) {
  ProgressiveRenderer engine;
  Scene before = scene;
  before.lights[0].position += glm::vec3(0.0f, 2.0f, 0.0f);
  engine.set_scene(before);
  EXPECT_TRUE(engine.wait_converged(60000));
  engine.set_scene(scene);
  EXPECT_TRUE(engine.wait_converged(60000));
  return engine.latest()->images;
}

std::vector<std::pair<std::string, Renderer>> renderers() {
  return {{"fresh", [](const Scene& s) { return render(s); }},
          {"light move (cached)", render_after_light_move},
          {"reference float", [](const Scene& s) { return render_reference<float>(s); }},
          {"reference double", [](const Scene& s) { return render_reference<double>(s); }}};
}

TEST(ShadowTerminator, AConvexSmoothMeshIsItsUnshadowedSelfOnEveryPath) {
  Scene shadowed = test::faceted_sphere_scene();
  shadowed.render.shadows = true;
  Scene open = shadowed;
  open.render.shadows = false;
  for (const auto& [name, render_with] : renderers()) {
    const TermImages on = render_with(shadowed), off = render_with(open);
    int lit = 0, dropped = 0;
    for (std::size_t i = 0; i < off.diffuse.pixels.size(); ++i) {
      lit += off.diffuse.pixels[i].x > 0.02f;
      dropped += off.diffuse.pixels[i].x - on.diffuse.pixels[i].x > 0.02f;
    }
    EXPECT_GT(lit, 1500) << name;  // the lit side fills a good part of the view
    EXPECT_EQ(dropped, 0) << name << ": " << dropped << " pixels lost their light to the facets";
  }
}

}  // namespace
}  // namespace gloss
