// The scaling rows of `gloss-cli bench --scaling`: each variant changes only its factor of the
// benchmark scene, by counts worked out by hand, and a row measures or says why it did not.
#include "analysis/bench/bench_scaling.h"

#include <cstdlib>

#include <gtest/gtest.h>

#include "base/assets.h"
#include "base/error.h"
#include "io/scene/scene_loader.h"

namespace gloss {
namespace {

Scene bench_scene() {
  return load_scene(asset_path("scenes/cornell-teapot.json"));
}

long long triangles(const Scene& scene) {
  long long n = 0;
  for (const Object& o : scene.objects)
    if (o.mesh) n += static_cast<long long>(o.mesh->triangles.size());
  return n;
}

long long teapot_triangles_of(const Scene& scene) {
  long long n = 0;
  for (const Object& o : scene.objects)
    if (o.type == ObjectType::teapot) n += static_cast<long long>(o.mesh->triangles.size());
  return n;
}

TEST(BenchScaling, RowsVaryOneFactorAtATime) {
  const std::vector<ScalingSetup> rows = scaling_setups();
  ASSERT_EQ(rows.size(), 9u);
  int lights = 0, teapots = 0, sizes = 0;
  for (const ScalingSetup& r : rows) {
    const bool base_lights = r.lights == 1, base_teapot = r.teapot_level == 0;
    const bool base_size = r.width == 1280 && r.height == 720;
    // At most one factor away from the benchmark scene.
    EXPECT_GE(int(base_lights) + int(base_teapot) + int(base_size), 2);
    lights += !base_lights;
    teapots += !base_teapot;
    sizes += !base_size;
  }
  EXPECT_EQ(lights, 3);   // 4, 16, 64
  EXPECT_EQ(teapots, 3);  // the grid at three levels
  EXPECT_EQ(sizes, 2);    // 1440p, 4K
}

TEST(BenchScaling, LightsAreSpreadWithTheirShareOfTheColour) {
  const Scene base = bench_scene();
  const Scene one = scaling_scene(base, {1, 0, 64, 36});
  ASSERT_EQ(one.lights.size(), 1u);
  EXPECT_EQ(one.lights[0].position, base.lights[0].position);
  const Scene sixteen = scaling_scene(base, {16, 0, 64, 36});
  ASSERT_EQ(sixteen.lights.size(), 16u);
  for (std::size_t i = 0; i < 16; ++i) {
    EXPECT_EQ(sixteen.lights[i].diffuse, base.lights[0].diffuse / 16.0f);
    EXPECT_EQ(sixteen.lights[i].position.y, base.lights[0].position.y);  // under the ceiling
    for (std::size_t j = 0; j < i; ++j)
      EXPECT_NE(sixteen.lights[i].position, sixteen.lights[j].position);
  }
  EXPECT_EQ(triangles(sixteen), triangles(base));
  EXPECT_EQ(sixteen.render.width, 64);
  EXPECT_EQ(sixteen.render.height, 36);
  EXPECT_EQ(sixteen.render.spp, 1);
}

TEST(BenchScaling, TheTeapotGridHoldsFortyNineTeapotsAtTheLevel) {
  const Scene base = bench_scene();
  const Scene grid = scaling_scene(base, {1, 4, 64, 36});
  int teapots = 0;
  for (const Object& o : grid.objects) teapots += o.type == ObjectType::teapot;
  EXPECT_EQ(teapots, 49);
  // Each teapot of the grid is the benchmark's teapot at level 4 (32 patches x 2 x 16
  // triangles, less the degenerate ones at the lid's and bottom's poles); the walls stay.
  const long long one = teapot_triangles_of(with_teapot_tessellation(base, 4));
  EXPECT_LE(one, 32 * 2 * 16);
  EXPECT_GT(one, 32 * 2 * 16 * 9 / 10);
  EXPECT_EQ(teapot_triangles_of(grid), 49 * one);
  EXPECT_EQ(triangles(grid) - teapot_triangles_of(grid),
            triangles(base) - teapot_triangles_of(base));
  EXPECT_EQ(grid.lights.size(), base.lights.size());
}

TEST(BenchScaling, ARowMeasuresOrSaysWhyNot) {
  const Scene base = bench_scene();
  const ScalingPoint p = run_scaling_row(base, {4, 0, 64, 36}, 1);
  EXPECT_TRUE(p.skipped.empty()) << p.skipped;
  EXPECT_GT(p.retrace_ms, 0.0);
  EXPECT_GT(p.embree_raw_ms, 0.0);
  EXPECT_GT(p.ratio, 0.0);
  EXPECT_EQ(p.triangles, triangles(base));
  // The point survives the trip from the row's process to the CLI.
  const ScalingPoint back = parse_scaling_point(scaling_point_json_text(p));
  EXPECT_EQ(back.setup.lights, 4);
  EXPECT_EQ(back.setup.width, 64);
  EXPECT_EQ(back.triangles, p.triangles);
  EXPECT_DOUBLE_EQ(back.ratio, p.ratio);
  // 10 M triangles do not fit a 1 MB budget: the row is skipped, with the reason.
  ::setenv("GLOSS_MEMORY_BUDGET_MB", "1", 1);
  const ScalingPoint over = run_scaling_row(base, {1, 57, 64, 36}, 1);
  ::unsetenv("GLOSS_MEMORY_BUDGET_MB");
  EXPECT_NE(over.skipped.find("budget"), std::string::npos) << over.skipped;
  EXPECT_EQ(over.retrace_ms, 0.0);
}

TEST(BenchScaling, SetupsTravelAsText) {
  const ScalingSetup s = parse_scaling_setup(scaling_setup_text({16, 18, 2560, 1440}));
  EXPECT_EQ(s.lights, 16);
  EXPECT_EQ(s.teapot_level, 18);
  EXPECT_EQ(s.width, 2560);
  EXPECT_EQ(s.height, 1440);
  EXPECT_THROW(parse_scaling_setup("16,18,2560"), InputError);
  EXPECT_THROW(parse_scaling_setup("0,0,64,36"), InputError);
  EXPECT_THROW(parse_scaling_setup("1,0,64,36x"), InputError);
}

}  // namespace
}  // namespace gloss
