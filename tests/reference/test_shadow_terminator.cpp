// A coarse smooth mesh keeps its light up to the terminator its vertex normals give (issue 22's
// second new-user review: normal-mapped models went black in steps along the triangles past the
// faceted terminator). A convex mesh alone in the scene can shadow only itself, so with the
// shadow ray leaving from the smooth surface (shading/surface.h terminator_lift) its image with
// shadows on is its image with shadows off, on every path: the fresh render, the cached light
// move, the reference in both precisions. Without the lift (measured with it taken out of
// shadow_ray_origin), 278 of the 1608 lit pixels of 12 x 6 faces at 128 x 128 lost more than 0.02
// of their diffuse (kd 0.5) on each path.
#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

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

// A unit UV sphere of `segments` around and `rings` from pole to pole, unit radial normals.
Mesh uv_sphere(int segments, int rings) {
  const double pi = 3.14159265358979323846;
  Mesh m;
  for (int r = 0; r <= rings; ++r) {
    for (int s = 0; s <= segments; ++s) {
      const double theta = pi * r / rings, phi = 2 * pi * s / segments;
      const glm::vec3 p(static_cast<float>(std::sin(theta) * std::cos(phi)),
                        static_cast<float>(std::cos(theta)),
                        static_cast<float>(std::sin(theta) * std::sin(phi)));
      m.positions.push_back(p);
      m.normals.push_back(glm::normalize(p));
    }
  }
  const auto at = [&](int r, int s) { return static_cast<unsigned>(r * (segments + 1) + s); };
  for (int r = 0; r < rings; ++r) {
    for (int s = 0; s < segments; ++s) {
      // Outward winding; the pole rows' zero-area triangles left out.
      if (r > 0) m.triangles.push_back({at(r, s), at(r, s + 1), at(r + 1, s)});
      if (r < rings - 1) m.triangles.push_back({at(r, s + 1), at(r + 1, s + 1), at(r + 1, s)});
    }
  }
  return m;
}

Scene faceted_sphere_scene() {
  Scene scene;
  scene.camera.eye = {0, 0.4f, 3.2f};
  scene.camera.target = {0, 0, 0};
  scene.camera.up = {0, 1, 0};
  scene.camera.fov_y = 45;
  scene.ambient = glm::vec3(0.0f);
  test::add_material(
      scene, "grey",
      test::make_material(glm::vec3(0.0f), glm::vec3(0.5f), glm::vec3(0.0f), glm::vec3(0.0f), 1));
  // From the right and a little behind: the terminator crosses the visible side.
  scene.lights.push_back(test::make_light({30, 6, -12}));
  Object o;
  o.name = "faceted";
  o.type = ObjectType::mesh;
  o.shape = o.mesh = std::make_shared<const Mesh>(uv_sphere(12, 6));
  scene.objects.push_back(o);
  scene.render.width = 128;
  scene.render.height = 128;
  return scene;
}

TEST(ShadowTerminator, AConvexSmoothMeshIsItsUnshadowedSelfOnEveryPath) {
  Scene shadowed = faceted_sphere_scene();
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
