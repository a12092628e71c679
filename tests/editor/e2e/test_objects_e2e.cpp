// A user's flow with objects and materials (issue 24), in the real gloss under Xvfb driven by
// --script: three models added and arranged on the floor, named, a material renamed and reused,
// the scene saved where the file panel proposes (the user's documents folder, not the shipped
// scene's); then a gizmo drag of the mouse, which moves an object by what the cursor moved and
// is taken back by one undo. Checked through the files gloss writes.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "editor/e2e/editor_process.h"
#include "io/scene/scene_loader.h"
#include "scene/geometry/placement.h"

namespace gloss {
namespace {

namespace fs = std::filesystem;

class ObjectsE2E : public test::EditorProcessTest {
 protected:
  ObjectsE2E() : EditorProcessTest("gloss-objects-e2e-") {}

  // The user's documents folder, as xdg-user-dirs names it in the run's config folder.
  fs::path documents() {
    const fs::path docs = m_dir / "Documents";
    fs::create_directories(docs);
    fs::create_directories(m_dir / "config");
    std::ofstream(m_dir / "config" / "user-dirs.dirs")
        << "XDG_DOCUMENTS_DIR=\"" << docs.string() << "\"\n";
    return docs;
  }
};

std::string data(const std::string& name) {
  return std::string(GLOSS_TEST_DATA_DIR) + "/obj/" + name;
}

int named(const Scene& scene, const std::string& name) {
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    if (scene.objects[i].name == name) return static_cast<int>(i);
  }
  ADD_FAILURE() << "no object " << name;
  return 0;
}

bool overlap(const Object& a, const Object& b) {
  glm::vec3 alo, ahi, blo, bhi;
  object_bounds(a, alo, ahi);
  object_bounds(b, blo, bhi);
  for (int k = 0; k < 3; ++k) {
    if (!(alo[k] < bhi[k] - 1e-4f && blo[k] < ahi[k] - 1e-4f)) return false;
  }
  return true;
}

TEST_F(ObjectsE2E, ThreeModelsArrangedNamedAndSavedWhereTheUserExpects) {
  const fs::path docs = documents();
  const std::string scene_file = std::string(GLOSS_APP_TEST_DATA) + "/floor_room.json";
  const test::EditorRun r = run_editor(scene_file,
                                       "wait\n"
                                       "browse save-scene\n"
                                       "object add model " +
                                           data("cube.obj") +
                                           "\n"
                                           "object add model " +
                                           data("tetra_no_normals.obj") +
                                           "\n"
                                           "object add model " +
                                           data("two_materials.obj") +
                                           "\n"
                                           "save " +
                                           (docs / "placed.json").string() +
                                           "\n"
                                           "object cube name crate\n"
                                           "object tetra_no_normals name \"small pyramid\"\n"
                                           "object crate rotate 0 30 0\n"
                                           "object \"small pyramid\" move 0 0 0.25\n"
                                           "material rename cube/red \"polished brass\"\n"
                                           "assign \"small pyramid\" \"polished brass\"\n"
                                           "wait\n"
                                           "screenshot shots/flow.png window\n"
                                           "save " +
                                           (docs / "floor_room.json").string() +
                                           "\n"
                                           "quit\n",
                                       true);
  if (r.status == -1) GTEST_SKIP() << "no xvfb-run";
  ASSERT_EQ(r.status, 0) << r.err;
  // The file panel starts in the user's documents with the scene's name, not in the data folder.
  EXPECT_NE(r.out.find("browse: " + docs.string() + " | floor_room.json"), std::string::npos)
      << r.out;
  // As added: each model on the floor (y = 0; the two parts of the last one together), clear of
  // each other and of the ball.
  const Scene placed = load_scene((docs / "placed.json").string());
  ASSERT_EQ(placed.objects.size(), 6u);  // ball, floor, cube, tetra, two_materials' two parts
  const int cube = named(placed, "cube"), tetra = named(placed, "tetra_no_normals");
  const int red = named(placed, "two_materials/red"), glow = named(placed, "two_materials/glow");
  for (int i : {cube, tetra, red, glow}) {
    for (int k : {0, cube, tetra, red, glow}) {
      if (k == i || (i == red && k == glow) || (i == glow && k == red)) continue;
      EXPECT_FALSE(overlap(placed.objects[i], placed.objects[k]))
          << placed.objects[i].name << " and " << placed.objects[k].name;
    }
  }
  glm::vec3 lo[4], hi[4];
  for (int n = 0; n < 4; ++n) ASSERT_TRUE(object_bounds(placed.objects[2 + n], lo[n], hi[n]));
  EXPECT_NEAR(lo[0].y, 0.0f, 1e-5f);
  EXPECT_NEAR(lo[1].y, 0.0f, 1e-5f);
  EXPECT_NEAR(std::min(lo[2].y, lo[3].y), 0.0f, 1e-5f);
  // Arranged, named and reused: the crate's renamed material is the pyramid's too.
  const Scene saved = load_scene((docs / "floor_room.json").string());
  const int crate = named(saved, "crate"), pyramid = named(saved, "small pyramid");
  EXPECT_EQ(saved.objects[crate].material, saved.objects[pyramid].material);
  EXPECT_EQ(saved.material_names[saved.objects[crate].material], "polished brass");
  EXPECT_EQ(saved.objects[crate].transform.rotate, glm::vec3(0, 30, 0));
  glm::vec3 a, b;
  ASSERT_TRUE(object_bounds(saved.objects[crate], a, b));
  EXPECT_NEAR(a.y, 0.0f, 1e-5f);  // turned about the vertical: still on the floor
  ASSERT_TRUE(object_bounds(saved.objects[pyramid], a, b));
  EXPECT_NEAR(a.z, lo[1].z + 0.25f, 1e-5f);  // moved 0.25 along z
  EXPECT_TRUE(fs::exists(m_dir / "shots" / "flow.png"));
}

// Where the pivot of object i is in the image, as fractions of its width and height.
glm::vec2 image_fraction(const Scene& scene, const glm::vec3& p) {
  const CameraBasis<double> b =
      make_camera_basis<double>(scene.camera, scene.render.width, scene.render.height);
  const glm::dvec3 d = glm::dvec3(p) - b.eye;
  const double z = glm::dot(d, b.forward);
  return glm::vec2((glm::dot(d, b.right) / z / b.scale_x + 1.0) * 0.5,
                   (1.0 - glm::dot(d, b.up) / z / b.scale_y) * 0.5);
}

TEST_F(ObjectsE2E, AGizmoDragMovesByWhatTheCursorMovedAndOneUndoTakesItBack) {
  const fs::path docs = documents();
  const std::string scene_file = std::string(GLOSS_APP_TEST_DATA) + "/floor_room.json";
  const Scene scene = load_scene(scene_file);
  // The ball's gizmo centre is its centre; the drag grabs the centre disc (the plane facing the
  // camera) and moves 0.2 of the image to the right.
  const glm::vec2 f = image_fraction(scene, scene.objects[0].center);
  char press[160], half[80], end[80];
  std::snprintf(press, sizeof press, "mouse press %.5f %.5f\n", f.x, f.y);
  std::snprintf(half, sizeof half, "mouse move %.5f %.5f\n", f.x + 0.1f, f.y);
  std::snprintf(end, sizeof end, "mouse move %.5f %.5f\n", f.x + 0.2f, f.y);
  const test::EditorRun r =
      run_editor(scene_file,
                 std::string("select 0\nwait\n") + press + half + "sleep 0.3\n" +
                     "screenshot shots/mid-drag.png window\n" + end + "mouse release\nwait\n" +
                     "save " + (docs / "moved.json").string() + "\nundo\n" + "save " +
                     (docs / "undone.json").string() + "\nquit\n",
                 true);
  if (r.status == -1) GTEST_SKIP() << "no xvfb-run";
  ASSERT_EQ(r.status, 0) << r.err;
  const Scene moved = load_scene((docs / "moved.json").string());
  const Scene undone = load_scene((docs / "undone.json").string());
  // The camera's right is +x (it looks down -z): at the ball's depth d along the view, 0.2 of
  // the image is 0.2 x 2 d tan(20 deg) x (320 / 240) world units.
  const CameraBasis<double> b = make_camera_basis<double>(scene.camera, 320, 240);
  const double depth = glm::dot(glm::dvec3(scene.objects[0].center) - b.eye, b.forward);
  const double expected = 0.2 * 2.0 * depth * std::tan(20.0 * 3.14159265358979 / 180.0) * 4.0 / 3.0;
  const glm::vec3 t = moved.objects[0].transform.translate;
  EXPECT_NEAR(t.x, expected, 0.01 * expected);
  EXPECT_NEAR(t.y, 0.0f, 1e-4f);
  EXPECT_NEAR(t.z, 0.0f, 1e-4f);
  EXPECT_EQ(undone.objects[0].transform, scene.objects[0].transform);  // one step, all of it
  EXPECT_TRUE(fs::exists(m_dir / "shots" / "mid-drag.png"));
}

}  // namespace
}  // namespace gloss
