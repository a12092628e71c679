// Automatic's choice for drags (automatic_choice.h): the raster path while it is timed, then
// the renderer whose images reach the screen sooner in a drag, decided once per setup.
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

// The measurements before a decision: the ray tracer's cold then warm re-trace at rest (pass_ms
// counted) and the raster path's first then second drag image (raster_ms counted).
void time_both(AutomaticChoice& choice, const DragSetup& s, double pass_ms, double raster_ms) {
  choice.ray_traced_pass(s, 40.0);
  choice.ray_traced_pass(s, pass_ms);
  choice.drag_image(s, true, 80.0);
  choice.drag_image(s, true, raster_ms);
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

TEST(AutomaticChoice, TheFirstDragsGoToTheRasterPathWhileItIsTimed) {
  AutomaticChoice choice;
  const DragSetup s = setup_1280();
  EXPECT_TRUE(choice.raster_for(s));
  choice.ray_traced_pass(s, 37.0);  // a renderer's first pass fills fresh caches: not counted
  EXPECT_EQ(choice.ray_traced_pass_ms(s), -1.0);
  choice.ray_traced_pass(s, 13.0);
  EXPECT_EQ(choice.ray_traced_pass_ms(s), 13.0);
  EXPECT_TRUE(choice.raster_for(s));
  // The first raster image may carry program builds: not counted.
  choice.drag_image(s, true, 500.0);
  EXPECT_EQ(choice.raster_ms(s), -1.0);
  EXPECT_TRUE(choice.raster_for(s));
}

TEST(AutomaticChoice, RasterNoSlowerThanTheRayTracersPassAtRestIsDecidedAtOnce) {
  AutomaticChoice choice;
  const DragSetup s = setup_1280();
  time_both(choice, s, 22.0, 21.0);
  EXPECT_TRUE(choice.raster_for(s));  // a drag's delay is at least the pass: raster no slower
  // Decided: later figures of this setup are not recorded, the decision stays.
  choice.drag_image(s, true, 90.0);
  choice.ray_traced_pass(s, 5.0);
  EXPECT_TRUE(choice.raster_for(s));
  EXPECT_EQ(choice.raster_ms(s), 21.0);
  EXPECT_EQ(choice.ray_traced_pass_ms(s), 22.0);
}

// A raster delay over the ray tracer's pass at rest proves nothing (the ray tracer's delay in a
// drag also has the UI's frames and the restarts in it): one drag times the ray tracer, then
// the faster takes the drags.
TEST(AutomaticChoice, OtherwiseOneDragTimesTheRayTracerAndTheFasterWins) {
  for (const double traced_drag : {100.0, 20.0}) {
    AutomaticChoice choice;
    const DragSetup s = setup_1280();
    time_both(choice, s, 22.0, 35.0);
    EXPECT_FALSE(choice.raster_for(s)) << traced_drag;  // the ray tracer's timing drag
    EXPECT_FALSE(choice.raster_for(s)) << traced_drag;  // not decided: the same until timed
    choice.drag_image(s, false, traced_drag);
    EXPECT_EQ(choice.ray_traced_ms(s), traced_drag);
    const bool raster = 35.0 <= traced_drag;
    EXPECT_EQ(choice.raster_for(s), raster) << traced_drag;
    choice.drag_image(s, false, raster ? 1.0 : 1000.0);  // decided: not recorded, no flip
    EXPECT_EQ(choice.raster_for(s), raster) << traced_drag;
    EXPECT_EQ(choice.would_raster(s), raster) << traced_drag;
  }
}

// A light drag makes the ray tracer re-light, not re-trace: its pass at rest bounds nothing, so
// the ray tracer is timed in a drag before raster is chosen.
TEST(AutomaticChoice, ALightDragIsDecidedOnlyOnTheRayTracersDragDelay) {
  AutomaticChoice choice;
  DragSetup s = setup_1280();
  s.light_drag = true;
  choice.ray_traced_pass(s, 40.0);
  choice.ray_traced_pass(s, 30.0);
  EXPECT_TRUE(choice.raster_for(s));
  choice.drag_image(s, true, 80.0);
  choice.drag_image(s, true, 20.0);  // within the re-trace at rest, but that is no bound here
  EXPECT_FALSE(choice.raster_for(s));
  choice.drag_image(s, false, 12.0);  // re-lighting is quick
  EXPECT_FALSE(choice.raster_for(s));
  EXPECT_EQ(choice.ray_traced_ms(s), 12.0);
}

// Decisions are kept per setup: alternating camera and light drags re-times neither.
TEST(AutomaticChoice, DecisionsOfSeveralSetupsAreKept) {
  AutomaticChoice choice;
  DragSetup camera = setup_1280();
  DragSetup light = camera;
  light.light_drag = true;
  time_both(choice, camera, 30.0, 20.0);
  EXPECT_TRUE(choice.raster_for(camera));  // 20 <= 30: decided
  choice.drag_image(light, true, 80.0);
  choice.drag_image(light, true, 45.0);
  choice.drag_image(light, false, 12.0);
  EXPECT_FALSE(choice.raster_for(light));  // 45 > 12: decided
  EXPECT_TRUE(choice.raster_for(camera));
  EXPECT_EQ(choice.raster_ms(camera), 20.0);
  EXPECT_FALSE(choice.raster_for(light));
  EXPECT_EQ(choice.raster_ms(light), 45.0);
}

TEST(AutomaticChoice, ANewRayTracersFirstPassIsNotCounted) {
  AutomaticChoice choice;
  const DragSetup s = setup_1280();
  choice.ray_traced_pass(s, 40.0);
  choice.ray_traced_pass(s, 20.0);
  choice.ray_tracer_restarted();
  choice.ray_traced_pass(s, 90.0);  // cold
  EXPECT_EQ(choice.ray_traced_pass_ms(s), 20.0);
  choice.ray_traced_pass(s, 22.0);
  EXPECT_EQ(choice.ray_traced_pass_ms(s), 22.0);
}

TEST(AutomaticChoice, ANewSetupIsMeasuredAfresh) {
  AutomaticChoice choice;
  DragSetup s = setup_1280();
  choice.ray_traced_pass(s, 37.0);
  choice.ray_traced_pass(s, 13.0);
  choice.drag_image(s, true, 19.0);
  choice.drag_image(s, true, 19.0);
  choice.drag_image(s, false, 60.0);
  EXPECT_TRUE(choice.raster_for(s));
  // Figures of another setup replace the stored ones, not the decision or what it rested on.
  DragSetup bigger = s;
  bigger.width = 1920;
  choice.drag_image(bigger, true, 50.0);
  choice.drag_image(bigger, true, 50.0);
  EXPECT_EQ(choice.raster_ms(bigger), 50.0);
  EXPECT_EQ(choice.raster_ms(s), 19.0);
  EXPECT_TRUE(choice.raster_for(s));
  // Shadows off: every figure is of another image.
  DragSetup off = s;
  off.shadows = false;
  EXPECT_EQ(choice.raster_ms(off), -1.0);
  EXPECT_EQ(choice.ray_traced_ms(off), -1.0);
  EXPECT_EQ(choice.ray_traced_pass_ms(off), -1.0);
  EXPECT_TRUE(choice.raster_for(off));
  // A light drag: the raster path redraws its shadow maps, the ray tracer re-lights; both drag
  // delays are its own, the re-trace at rest is shared.
  DragSetup light = s;
  light.light_drag = true;
  EXPECT_EQ(choice.raster_ms(light), -1.0);
  EXPECT_EQ(choice.ray_traced_ms(light), -1.0);
  EXPECT_EQ(choice.ray_traced_pass_ms(light), 13.0);
  // Per-vertex shading is a raster knob: the ray tracer's figures still hold.
  DragSetup vertex = s;
  vertex.raster.shading = ShadingFrequency::vertex;
  EXPECT_EQ(choice.raster_ms(vertex), -1.0);
  EXPECT_EQ(choice.ray_traced_ms(vertex), 60.0);
}

}  // namespace
}  // namespace gloss
