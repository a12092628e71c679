// New objects (new_objects.h): scaled to the scene, their lowest point on the surface below,
// clear of the objects already there; model parts without a material of their own get the grey
// default.
#include "editor/model/document/new_objects.h"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "base/error.h"
#include "editor/model/document/command_layer.h"
#include "io/scene/scene_loader.h"
#include "scene/geometry/placement.h"
#include "support/scratch_folder.h"

namespace gloss {
namespace {

Scene shipped(const std::string& name) {
  return load_scene(std::string(GLOSS_SCENES_DIR) + "/" + name + ".json");
}

Scene with(const Scene& scene, const AddObjects& add) {
  CommandLayer layer(scene);
  layer.execute(add);
  return layer.scene();
}

// The placed objects' boxes overlap (touching faces do not count).
bool boxes_overlap(const Object& a, const Object& b) {
  glm::vec3 alo, ahi, blo, bhi;
  if (!object_bounds(a, alo, ahi) || !object_bounds(b, blo, bhi)) return false;
  for (int k = 0; k < 3; ++k) {
    if (!(alo[k] < bhi[k] - 1e-4f && blo[k] < ahi[k] - 1e-4f)) return false;
  }
  return true;
}

// Every new object of after (those past before's count) rests on y = floor and overlaps none
// of the objects that were there, the floor aside (index floor_index).
void expect_set_down_beside(const Scene& before, const Scene& after, float floor, int floor_index) {
  for (std::size_t n = before.objects.size(); n < after.objects.size(); ++n) {
    const Object& o = after.objects[n];
    glm::vec3 lo, hi;
    ASSERT_TRUE(object_bounds(o, lo, hi));
    EXPECT_NEAR(lo.y, floor, 1e-5f) << o.name;
    for (std::size_t k = 0; k < before.objects.size(); ++k) {
      if (static_cast<int>(k) == floor_index) continue;
      EXPECT_FALSE(boxes_overlap(o, before.objects[k]))
          << o.name << " in " << before.objects[k].name;
    }
  }
}

TEST(NewObjects, TheSizeFollowsTheSceneSolidObjects) {
  // spheres.json: two spheres 2 wide on a 16-wide floor: the median solid is 2, under 0.35 x 16.
  EXPECT_FLOAT_EQ(new_object_size(shipped("spheres")), 2.0f);
  // cornell.json: the blocks' upright sides are quads turned off the axes, so their boxes are
  // solid: four 0.595 (the short block's height) and four 1.189 (the tall one's); the median,
  // 1.189, is cut to 0.35 of the room's 2.
  EXPECT_FLOAT_EQ(new_object_size(shipped("cornell")), 0.7f);
  // cornell.json without its blocks: only flat walls, 0.3 of the room.
  Scene room = shipped("cornell");
  room.objects.resize(5);
  EXPECT_FLOAT_EQ(new_object_size(room), 0.6f);
  EXPECT_FLOAT_EQ(new_object_size(Scene{}), 2.0f);
}

TEST(NewObjects, APrimitiveRestsOnTheFloorBesideTheSpheres) {
  const Scene scene = shipped("spheres");  // floor quad at y = 0, index 2
  for (ObjectType type :
       {ObjectType::sphere, ObjectType::box, ObjectType::teapot, ObjectType::quad}) {
    const AddObjects add = primitive_objects(scene, type);
    ASSERT_EQ(add.objects.size(), 1u);
    const Scene after = with(scene, add);
    expect_set_down_beside(scene, after, 0.0f, 2);
    const Object& o = after.objects.back();
    EXPECT_EQ(o.name, to_string(type));
    EXPECT_EQ(after.material_names[o.material], to_string(type));  // its own material
    EXPECT_EQ(after.materials[o.material].diffuse, Material{}.diffuse);
    EXPECT_TRUE(is_identity(o.transform));
  }
  const Object ball = with(scene, primitive_objects(scene, ObjectType::sphere)).objects.back();
  EXPECT_FLOAT_EQ(ball.radius, 1.0f);  // new_object_size / 2
}

TEST(NewObjects, ASecondPrimitiveGoesBesideTheFirst) {
  Scene scene = shipped("spheres");
  scene = with(scene, primitive_objects(scene, ObjectType::box));
  const Scene after = with(scene, primitive_objects(scene, ObjectType::box));
  EXPECT_EQ(after.objects.back().name, "box 2");
  EXPECT_EQ(after.material_names[after.objects.back().material], "box 2");
  expect_set_down_beside(scene, after, 0.0f, 2);
}

TEST(NewObjects, NewBoxesHideNeitherSphereFromTheCamera) {
  // spheres.json frames its two spheres (centres (+-1.15, 1, 0)) from (0, 2.2, 7.5): the free
  // ground in the image lies in front of and behind them. Three boxes 2 wide are added in turn;
  // the sight line from the eye to each sphere's centre, sampled every 1/1000 of its length,
  // enters none of them (a box placed straight in front, at z = 2.5, would cover both).
  Scene scene = shipped("spheres");
  const std::size_t first = scene.objects.size();
  for (int n = 0; n < 3; ++n) scene = with(scene, primitive_objects(scene, ObjectType::box));
  const glm::vec3 eye = scene.camera.eye;
  for (std::size_t k = first; k < scene.objects.size(); ++k) {
    glm::vec3 lo, hi;
    ASSERT_TRUE(object_bounds(scene.objects[k], lo, hi));
    for (const glm::vec3 centre : {glm::vec3(-1.15f, 1, 0), glm::vec3(1.15f, 1, 0)}) {
      for (int i = 0; i <= 1000; ++i) {
        const glm::vec3 p = eye + (centre - eye) * (i / 1000.0f);
        const bool inside = glm::all(glm::greaterThan(p, lo)) && glm::all(glm::lessThan(p, hi));
        ASSERT_FALSE(inside) << scene.objects[k].name << " hides the sphere at x " << centre.x;
      }
    }
  }
}

TEST(NewObjects, AModelIsScaledSetDownAndPlacedInsideTheCornellRoom) {
  const Scene scene = shipped("cornell");  // floor at y = -1; walls at x, z = +-1
  const AddObjects add = model_objects(scene, std::string(GLOSS_TEST_DATA_DIR) + "/obj/cube.obj");
  const Scene after = with(scene, add);
  glm::vec3 lo(1e9f), hi(-1e9f);
  for (std::size_t n = scene.objects.size(); n < after.objects.size(); ++n) {
    glm::vec3 a, b;
    ASSERT_TRUE(object_bounds(after.objects[n], a, b));
    lo = glm::min(lo, a);
    hi = glm::max(hi, b);
  }
  EXPECT_NEAR(lo.y, -1.0f, 1e-5f);        // on the floor
  EXPECT_NEAR(hi.x - lo.x, 0.7f, 1e-5f);  // new_object_size
  EXPECT_GT(lo.x, -1.0f);                 // inside the walls
  EXPECT_LT(hi.x, 1.0f);
  EXPECT_GT(lo.z, -1.0f);
  for (std::size_t k = 0; k < scene.objects.size(); ++k) {
    if (scene.material_names[scene.objects[k].material] == "floor") continue;
    for (std::size_t n = scene.objects.size(); n < after.objects.size(); ++n) {
      EXPECT_FALSE(boxes_overlap(after.objects[n], scene.objects[k])) << scene.objects[k].name;
    }
  }
  // The file's materials come along under the file's stem.
  EXPECT_EQ(after.material_names[after.objects.back().material].rfind("cube/", 0), 0u);
}

// A model's maps are named as a scene names files, the model's folder in front: a scene saved
// after adding the spider named its textures ("engineflare1.jpg") beside the scene, where they
// are not, and did not open again.
TEST(NewObjects, ATexturedModelsMapsAreFoundAgainWhenTheSavedSceneOpens) {
  const std::string file = "/usr/share/assimp/models/OBJ/spider.obj";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << "assimp-testmodels is not installed";
  const Scene scene = shipped("spheres");
  const Scene after = with(scene, model_objects(scene, file));
  int maps = 0;
  for (const Material& m : after.materials) {
    if (!m.has_map(MapSlot::diffuse)) continue;
    ++maps;
    // Relative to the scene's folder, as a saved scene names its maps.
    const std::string& name = m.map(MapSlot::diffuse).file;
    EXPECT_FALSE(std::filesystem::path(name).is_absolute()) << name;
    const std::filesystem::path file =
        (std::filesystem::path(scene.path).parent_path() / name).lexically_normal();
    EXPECT_EQ(std::filesystem::canonical(file).parent_path(), "/usr/share/assimp/models/OBJ")
        << name;
  }
  // Four: the faces use Skin, HLeibTex, BeinTex and Augentex; the MTL's Brusttex is unused.
  EXPECT_EQ(maps, 4);

  ScratchFolder folder;
  save_scene(after, folder.file("spider-scene.json"));
  Scene back;
  ASSERT_NO_THROW(back = load_scene(folder.file("spider-scene.json")));
  int back_maps = 0;
  for (const Material& m : back.materials) back_maps += m.has_map(MapSlot::diffuse) ? 1 : 0;
  EXPECT_EQ(back_maps, 4);
}

// A map held inside a model (an embedded image: MODEL#MATERIAL/SLOT) names the model as the
// object does, so the loader's cache finds the model read once (the object's file was absolute
// and the map's model relative: a saved scene read the model twice on opening).
TEST(NewObjects, AModelsOwnMapsNameTheModelAsItsObjectDoes) {
  const std::string file = "/usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << "assimp-testmodels is not installed";
  const Scene scene = shipped("spheres");
  const Scene after = with(scene, model_objects(scene, file));
  const Object& box = after.objects.back();
  EXPECT_FALSE(std::filesystem::path(box.params.file).is_absolute()) << box.params.file;
  const TextureMap& map = after.materials[box.material].map(MapSlot::diffuse);
  ASSERT_TRUE(map.present());
  EXPECT_EQ(map.file.rfind(box.params.file + "#", 0), 0u) << map.file << " / " << box.params.file;
}

TEST(NewObjects, InAnEmptySceneAModelIsCentredOnTheTarget) {
  Scene scene;
  scene.camera.target = {1, 2, 3};
  const Scene after =
      with(scene, model_objects(scene, std::string(GLOSS_TEST_DATA_DIR) + "/obj/cube.obj"));
  glm::vec3 lo, hi;
  ASSERT_TRUE(object_bounds(after.objects[0], lo, hi));
  EXPECT_NEAR(0.5f * (lo.x + hi.x), 1.0f, 1e-5f);
  EXPECT_NEAR(0.5f * (lo.y + hi.y), 2.0f, 1e-5f);
  EXPECT_NEAR(hi.y - lo.y, 2.0f, 1e-5f);  // 2 units in an empty scene
}

TEST(NewObjects, APlyWithoutColoursGetsTheGreyDefault) {
  ScratchFolder folder;
  std::ofstream(folder.file("tri.ply")) << "ply\nformat ascii 1.0\nelement vertex 3\n"
                                           "property float x\nproperty float y\n"
                                           "property float z\nelement face 1\n"
                                           "property list uchar int vertex_indices\n"
                                           "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  const Scene scene = shipped("spheres");
  const Scene after = with(scene, model_objects(scene, folder.file("tri.ply")));
  const Object& o = after.objects.back();
  EXPECT_EQ(after.material_names[o.material], "default");
  const Material& m = after.materials[o.material];
  const Material grey;  // ka 0.2, kd 0.8, ks 0: not assimp's white ka = kd = ks = 1
  EXPECT_EQ(m.ambient, grey.ambient);
  EXPECT_EQ(m.diffuse, grey.diffuse);
  EXPECT_EQ(m.specular, grey.specular);
  // The scene loader agrees: the same file as a mesh object without a material.
  const Scene loaded =
      parse_scene(R"({"objects": [{"type": "mesh", "file": ")" + folder.file("tri.ply") + R"("}]})",
                  folder.file("s.json"));
  EXPECT_EQ(loaded.material_names[loaded.objects[0].material], "default");
  EXPECT_EQ(loaded.materials[loaded.objects[0].material].diffuse, grey.diffuse);
}

TEST(NewObjects, AGltfBoxWithoutAMaterialGetsTheGreyDefault) {
  const std::string file = "/usr/share/assimp/models/glTF2/IncorrectVertexArrays/Cube.gltf";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << "assimp-testmodels is not installed";
  const Scene scene = shipped("spheres");
  const Scene after = with(scene, model_objects(scene, file));
  EXPECT_EQ(after.material_names[after.objects.back().material], "default");
  EXPECT_EQ(after.materials[after.objects.back().material].specular, glm::vec3(0.0f));
}

TEST(NewObjects, AMissingModelIsAnErrorNamingIt) {
  try {
    model_objects(Scene{}, "/no/such/model.obj");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/no/such/model.obj"), std::string::npos);
  }
}

}  // namespace
}  // namespace gloss
