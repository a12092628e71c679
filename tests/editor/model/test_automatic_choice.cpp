// Automatic's choice for drags (automatic_choice.h): the raster path while it is unmeasured,
// then whichever renderer's measured frame is faster, decided once per setup.
#include <gtest/gtest.h>

#include <memory>

#include "editor/model/view/automatic_choice.h"

namespace gloss {
namespace {

DragSetup setup_1280() {
  DragSetup s;
  s.width = 1280;
  s.height = 720;
  s.shadows = true;
  s.lights = 1;
  s.primitives = 100;
  return s;
}

TEST(DragSetup, CountsTrianglesAndSpheresAndNeedsALightForShadows) {
  Scene scene;
  scene.render.shadows = true;
  Object sphere;
  sphere.type = ObjectType::sphere;
  Object mesh;
  mesh.type = ObjectType::quad;
  auto triangles = std::make_shared<Mesh>();
  triangles->triangles.resize(2);
  mesh.mesh = triangles;
  scene.objects = {sphere, mesh, sphere};
  DragSetup s = drag_setup(scene, 64, 48, false, false, RasterSettings{}, false);
  EXPECT_EQ(s.primitives, 4u);  // 2 triangles + 2 spheres
  EXPECT_FALSE(s.shadows);      // no light: nothing casts a shadow
  scene.lights.resize(1);
  s = drag_setup(scene, 64, 48, false, false, RasterSettings{}, true);
  EXPECT_TRUE(s.shadows);
  EXPECT_EQ(s.lights, 1u);
  EXPECT_TRUE(s.light_drag);
}

TEST(AutomaticChoice, RasterWhileEitherSideIsUnmeasured) {
  AutomaticChoice choice;
  const DragSetup s = setup_1280();
  EXPECT_TRUE(choice.raster_for(s));
  choice.ray_traced_frame(s, 37.0);  // a renderer's first pass fills fresh caches: not counted
  EXPECT_EQ(choice.ray_traced_ms(s), -1.0);
  choice.ray_traced_frame(s, 13.0);
  EXPECT_EQ(choice.ray_traced_ms(s), 13.0);
  EXPECT_TRUE(choice.raster_for(s));
  // The first raster frame may carry program builds: not counted.
  choice.raster_frame(s, 500.0);
  EXPECT_EQ(choice.raster_ms(s), -1.0);
  EXPECT_TRUE(choice.raster_for(s));
}

TEST(AutomaticChoice, ASlowerRasterFrameSendsTheDragToTheRayTracer) {
  AutomaticChoice choice;
  const DragSetup s = setup_1280();
  choice.ray_traced_frame(s, 37.0);
  choice.ray_traced_frame(s, 13.0);
  choice.raster_frame(s, 80.0);
  choice.raster_frame(s, 19.0);
  EXPECT_EQ(choice.raster_ms(s), 19.0);
  EXPECT_EQ(choice.ray_traced_ms(s), 13.0);
  EXPECT_FALSE(choice.raster_for(s));
  // Decided for this setup: a slower re-trace later (another view) does not flip it back.
  choice.ray_traced_frame(s, 40.0);
  EXPECT_FALSE(choice.raster_for(s));
}

TEST(AutomaticChoice, AFasterOrEqualRasterFrameKeepsTheRasterPath) {
  AutomaticChoice choice;
  const DragSetup s = setup_1280();
  choice.ray_traced_frame(s, 37.0);
  choice.ray_traced_frame(s, 13.0);
  choice.raster_frame(s, 30.0);
  choice.raster_frame(s, 13.0);
  EXPECT_TRUE(choice.would_raster(s));
  EXPECT_TRUE(choice.raster_for(s));
}

TEST(AutomaticChoice, ANewSetupIsMeasuredAfresh) {
  AutomaticChoice choice;
  DragSetup s = setup_1280();
  choice.ray_traced_frame(s, 37.0);
  choice.ray_traced_frame(s, 13.0);
  choice.raster_frame(s, 19.0);
  choice.raster_frame(s, 19.0);
  EXPECT_FALSE(choice.raster_for(s));
  // Shadows off: both frames change, neither figure applies.
  DragSetup off = s;
  off.shadows = false;
  EXPECT_EQ(choice.raster_ms(off), -1.0);
  EXPECT_EQ(choice.ray_traced_ms(off), -1.0);
  EXPECT_TRUE(choice.raster_for(off));
  // A light drag redraws the shadow maps: the raster figure is its own, the re-trace is shared.
  DragSetup light = s;
  light.light_drag = true;
  EXPECT_EQ(choice.raster_ms(light), -1.0);
  EXPECT_EQ(choice.ray_traced_ms(light), 13.0);
  EXPECT_TRUE(choice.raster_for(light));
  // Per-vertex shading is a raster knob: the ray tracer's figure still holds.
  DragSetup vertex = s;
  vertex.raster.shading = ShadingFrequency::vertex;
  choice.raster_frame(vertex, 20.0);
  choice.raster_frame(vertex, 10.0);
  EXPECT_TRUE(choice.raster_for(vertex));
  EXPECT_EQ(choice.ray_traced_ms(vertex), 13.0);
}

}  // namespace
}  // namespace gloss
