// The undo history's memory: steps share the meshes that did not change, so 500 material edits of
// a scene with a 178k-triangle mesh hold 500 small scene copies and not one triangle more; and
// steps that keep replaced meshes alive (open, add model) are capped by bytes.
#include <memory>

#include <gtest/gtest.h>

#include "editor/model/document/command_layer.h"
#include "scene/memory/scene_bytes.h"
#include "support/field_commands.h"
#include "support/test_scene.h"

namespace gloss {
namespace {

// A flat grid of n x n vertices with normals: 2 (n - 1)^2 triangles.
std::shared_ptr<const Mesh> grid_mesh(unsigned n) {
  auto mesh = std::make_shared<Mesh>();
  for (unsigned y = 0; y < n; ++y) {
    for (unsigned x = 0; x < n; ++x) {
      mesh->positions.push_back({x * 0.01f, 0.0f, y * 0.01f});
      mesh->normals.push_back({0.0f, 1.0f, 0.0f});
    }
  }
  for (unsigned y = 0; y + 1 < n; ++y) {
    for (unsigned x = 0; x + 1 < n; ++x) {
      const unsigned i = y * n + x;
      mesh->triangles.push_back({i, i + n, i + 1});
      mesh->triangles.push_back({i + 1, i + n, i + n + 1});
    }
  }
  return mesh;
}

// The two spheres plus a mesh object of its own material.
Scene scene_with_mesh(std::shared_ptr<const Mesh> mesh) {
  Scene scene = test::two_sphere_scene();
  Object floor;
  floor.name = "floor";
  floor.type = ObjectType::mesh;
  floor.material = 1;
  floor.params.file = "models/a-large-model-file-name.obj";
  floor.mesh = std::move(mesh);
  scene.objects.push_back(floor);
  return scene;
}

// Besides its scene copy, a step holds its label and merge key and a few words; labels are
// under 100 characters ("set diffuse of object 2 (floor)").
constexpr std::uint64_t kStepOverheadBound = 256;

TEST(HistoryMemory, FiveHundredMaterialEditsOfALargeMeshCopyNoTriangles) {
  const std::shared_ptr<const Mesh> mesh = grid_mesh(300);
  ASSERT_EQ(mesh->triangles.size(), 2u * 299 * 299);
  // 90,000 positions and normals of 12 B, 178,802 triangles of 12 B: about 4.3 MB.
  const std::uint64_t one_mesh = mesh_bytes(*mesh);
  ASSERT_GE(one_mesh, (90000u * 24 + 178802u * 12));
  const Scene start = scene_with_mesh(mesh);
  CommandLayer layer(start);
  for (int i = 0; i < 500; ++i) {
    ASSERT_TRUE(layer.execute(test::set_material(2, "diffuse", glm::vec3(0.001f * (i + 1)))));
    layer.seal();
  }
  EXPECT_EQ(layer.undo_count(), 500u);
  // A copy's vectors have the capacity of their size (start's grew by push_back).
  const std::uint64_t copy = scene_bytes_without_meshes(Scene(start));
  EXPECT_GE(layer.history_bytes(), 500 * copy);
  EXPECT_LE(layer.history_bytes(), 500 * (copy + kStepOverheadBound));
  // 500 copies of a 3-object scene (about 1.5 kB each) weigh under a fifth of the one mesh they
  // share: a single copied triangle array would be more than the whole history.
  EXPECT_LT(layer.history_bytes(), one_mesh / 5);
  EXPECT_EQ(mesh.use_count(), 3 + 500);  // ours, start's, the document's and one per step

  for (int i = 0; i < 500; ++i) ASSERT_TRUE(layer.undo());
  EXPECT_EQ(layer.scene().materials[1].diffuse, start.materials[1].diffuse);
  EXPECT_EQ(layer.scene().objects[2].mesh.get(), mesh.get());
}

TEST(HistoryMemory, StepsThatKeepReplacedMeshesAliveAreCappedByBytes) {
  const std::uint64_t one_mesh = mesh_bytes(*grid_mesh(300));
  CommandLayer layer(scene_with_mesh(grid_mesh(300)));
  const Mesh* previous = nullptr;
  // 40 scenes of a distinct 4.3 MB mesh each: 170 MB if every step were kept.
  for (int i = 0; i < 40; ++i) {
    previous = layer.scene().objects[2].mesh.get();
    auto next = std::make_shared<const Scene>(scene_with_mesh(grid_mesh(300)));
    ASSERT_TRUE(layer.execute(ReplaceScene{next, "open"}));
  }
  EXPECT_LE(layer.history_bytes(), CommandLayer::kMaxHistoryBytes);
  // Each kept step holds the mesh it replaced: as many steps as fit, and at least one.
  const std::uint64_t fit = CommandLayer::kMaxHistoryBytes / one_mesh;
  EXPECT_EQ(layer.undo_count(), fit);
  EXPECT_GE(layer.history_bytes(), layer.undo_count() * one_mesh);
  ASSERT_TRUE(layer.undo());
  EXPECT_EQ(layer.scene().objects[2].mesh.get(), previous);
}

TEST(HistoryMemory, TheNewestStepStaysWhateverItsSize) {
  CommandLayer layer(scene_with_mesh(grid_mesh(300)));
  // A 1500 x 1500 grid is over 100 MB, over the cap on its own.
  layer.execute(ReplaceScene{std::make_shared<const Scene>(scene_with_mesh(grid_mesh(10))), "a"});
  const Scene big = scene_with_mesh(grid_mesh(1500));
  ASSERT_GT(mesh_bytes(*big.objects[2].mesh), CommandLayer::kMaxHistoryBytes);
  layer.execute(ReplaceScene{std::make_shared<const Scene>(big), "b"});
  layer.execute(ReplaceScene{std::make_shared<const Scene>(scene_with_mesh(grid_mesh(10))), "c"});
  EXPECT_EQ(layer.undo_count(), 1u);  // "c", holding the big scene; "a" and "b" went
  ASSERT_TRUE(layer.undo());
  EXPECT_EQ(layer.scene().objects[2].mesh.get(), big.objects[2].mesh.get());
}

}  // namespace
}  // namespace gloss
