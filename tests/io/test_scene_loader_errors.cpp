// Scene files that must be refused: every error is an InputError naming the file and either the
// line:column (syntax, positions worked out by hand from the test text) or the field path.
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "base/error.h"
#include "io/scene/scene_loader.h"
#include "support/scratch_folder.h"

namespace gloss {
namespace {

// A valid scene with one sphere using material "m"; tests splice one bad piece into it.
std::string scene_with(const std::string& camera, const std::string& light,
                       const std::string& material, const std::string& object,
                       const std::string& render) {
  return R"({"camera": )" + camera + R"(, "lights": [)" + light + R"(], "materials": {"m": )" +
         material + R"(}, "objects": [)" + object + R"(], "render": )" + render + "}";
}
const std::string kCamera = R"({"eye": [0, 0, 5], "target": [0, 0, 0], "up": [0, 1, 0]})";
const std::string kLight = R"({"position": [3, 3, 3]})";
const std::string kMaterial = R"({"preset": "gold"})";
const std::string kSphere =
    R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"})";
const std::string kRender = R"({"width": 64, "height": 48})";

std::string with_camera(const std::string& c) {
  return scene_with(c, kLight, kMaterial, kSphere, kRender);
}
std::string with_light(const std::string& l) {
  return scene_with(kCamera, l, kMaterial, kSphere, kRender);
}
std::string with_material(const std::string& m) {
  return scene_with(kCamera, kLight, m, kSphere, kRender);
}
std::string with_object(const std::string& o) {
  return scene_with(kCamera, kLight, kMaterial, o, kRender);
}
std::string with_render(const std::string& r) {
  return scene_with(kCamera, kLight, kMaterial, kSphere, r);
}

// Parses text as "bad.json" and returns the InputError it must throw.
InputError error_of(const std::string& text) {
  try {
    parse_scene(text, "bad.json");
  } catch (const InputError& error) {
    return error;
  }
  ADD_FAILURE() << "accepted: " << text;
  return InputError("", "");
}

void expect_field_error(const std::string& text, const std::string& field,
                        const std::string& fragment) {
  const InputError error = error_of(text);
  const std::string what = error.what();
  EXPECT_EQ(error.field(), field) << what;
  EXPECT_EQ(what.rfind("bad.json: " + field + ": ", 0), 0u) << what;
  EXPECT_NE(what.find(fragment), std::string::npos) << what;
}

TEST(SceneLoaderErrors, TheSceneItselfIsValid) {
  EXPECT_NO_THROW(parse_scene(with_object(kSphere), "bad.json"));
}

TEST(SceneLoaderErrors, MisplacedValueIsReportedAtItsLineAndColumn) {
  // Line 3 is 4 spaces, {"type": "sphere" then "radius": its closing quote is column 30.
  const InputError error =
      error_of("{\n  \"objects\": [\n    {\"type\": \"sphere\" \"radius\": 1}\n  ]\n}\n");
  EXPECT_EQ(error.line(), 3);
  EXPECT_EQ(error.column(), 30);
  EXPECT_EQ(std::string(error.what()).rfind("bad.json:3:30: ", 0), 0u) << error.what();
}

TEST(SceneLoaderErrors, TextThatIsNotJsonIsReportedAtTheFirstWrongCharacter) {
  // "not" starts like the literal null; the 'o' on line 3, column 2 is where it stops being one.
  const InputError error = error_of("\n\nnot json\n");
  EXPECT_EQ(error.line(), 3);
  EXPECT_EQ(error.column(), 2);
  EXPECT_NE(std::string(error.what()).find("bad.json:3:2"), std::string::npos);
}

TEST(SceneLoaderErrors, TruncatedFileIsReportedJustPastItsEnd) {
  // The last line, 4 spaces then {"type": "sphere" (17 characters), is 21 long: column 22.
  const InputError error = error_of("{\n  \"objects\": [\n    {\"type\": \"sphere\"");
  EXPECT_EQ(error.line(), 3);
  EXPECT_EQ(error.column(), 22);
}

TEST(SceneLoaderErrors, NumberBeyondDoubleRangeIsReportedWhereItStarts) {
  // Line 3: 2 spaces, "lights": [{"position": [0, then 1e999 starts at column 31.
  const InputError error =
      error_of("{\n  \"objects\": [],\n  \"lights\": [{\"position\": [0, 1e999, 0]}]\n}\n");
  EXPECT_EQ(error.line(), 3);
  EXPECT_EQ(error.column(), 31);
  EXPECT_EQ(std::string(error.what()).rfind("bad.json:3:31: ", 0), 0u) << error.what();
  EXPECT_NE(std::string(error.what()).find("1e999"), std::string::npos) << error.what();
}

TEST(SceneLoaderErrors, NumberBeyondFloatRangeNamesItsField) {
  expect_field_error(with_light(R"({"position": [0, 1e39, 0]})"), "lights[0].position[1]",
                     "finite");
}

TEST(SceneLoaderErrors, UnknownKeysNameTheNearestKnownKey) {
  expect_field_error(
      with_object(R"({"type": "sphere", "center": [0, 0, 0], "radus": 1, "material": "m"})"),
      "objects[0].radus", "unknown key 'radus' (did you mean 'radius'?)");
  expect_field_error(R"({"objets": []})", "objets", "(did you mean 'objects'?)");
  expect_field_error(with_render(R"({"widht": 64})"), "render.widht", "'width'");
  expect_field_error(with_camera(R"({"fov": 40})"), "camera.fov", "'fov_y'");
  expect_field_error(with_light(R"({"position": [1, 1, 1], "atenuation": [1, 0, 0]})"),
                     "lights[0].atenuation", "'attenuation'");
}

TEST(SceneLoaderErrors, MissingRequiredFieldsAreNamed) {
  expect_field_error(R"({"materials": {}})", "objects", "missing required field");
  expect_field_error(with_object(R"({"type": "sphere", "center": [0, 0, 0], "material": "m"})"),
                     "objects[0].radius", "missing required field");
  expect_field_error(with_object(R"({"center": [0, 0, 0], "radius": 1, "material": "m"})"),
                     "objects[0].type", "missing required field");
  expect_field_error(with_light(R"({"diffuse": [1, 1, 1]})"), "lights[0].position",
                     "missing required field");
}

TEST(SceneLoaderErrors, WrongTypesAndVectorSizesAreNamed) {
  expect_field_error(
      with_object(R"({"type": "sphere", "center": [0, 0, 0], "radius": "1", "material": "m"})"),
      "objects[0].radius", "expected a number, got a string");
  expect_field_error(
      with_object(R"({"type": "sphere", "center": [0, 0], "radius": 1, "material": "m"})"),
      "objects[0].center", "expected 3 numbers, got 2");
  expect_field_error(with_render(R"({"shadows": "yes"})"), "render.shadows", "true or false");
  expect_field_error(R"({"objects": {}})", "objects", "expected an array");
  expect_field_error(with_object(R"({"type": "quad", "vertices": [[0, 0, 0]], "material": "m"})"),
                     "objects[0].vertices", "4 corners");
}

TEST(SceneLoaderErrors, UnknownNamesSuggestTheNearestOnes) {
  expect_field_error(with_material(R"({"preset": "gld"})"), "materials.m.preset",
                     "unknown preset 'gld'");
  expect_field_error(with_render(R"({"model": "blinn_phong"})"), "render.model",
                     "unknown shading model 'blinn_phong' (did you mean 'blinn-phong'?)");
  expect_field_error(with_object(R"({"type": "spher", "center": [0, 0, 0], "radius": 1})"),
                     "objects[0].type", "(did you mean 'sphere'?)");
  expect_field_error(
      with_object(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "n"})"),
      "objects[0].material", "unknown material 'n' (did you mean 'm'?)");
  expect_field_error(with_render(R"({"pow": "fastest"})"), "render.pow", "'fast'");
}

TEST(SceneLoaderErrors, NegativeRadiusShininessAndColourAreRefused) {
  expect_field_error(
      with_object(R"({"type": "sphere", "center": [0, 0, 0], "radius": -1, "material": "m"})"),
      "objects[0].radius", "greater than 0");
  expect_field_error(with_material(R"({"preset": "gold", "shininess": -2})"),
                     "materials.m.shininess", "must be from 0 to 1000000, got -2");
  expect_field_error(with_material(R"({"diffuse": [0.5, -0.1, 0.5]})"), "materials.m.diffuse[1]",
                     "must be >= 0, got -0.1");
  expect_field_error(with_light(R"({"position": [1, 1, 1], "diffuse": [1, -1, 1]})"),
                     "lights[0].diffuse[1]", "must be >= 0, got -1");
}

TEST(SceneLoaderErrors, ImpossibleImageSizesAndSampleCountsAreRefused) {
  expect_field_error(with_render(R"({"width": 0})"), "render.width", "from 1 to 16384");
  expect_field_error(with_render(R"({"height": -480})"), "render.height", "from 1 to 16384");
  expect_field_error(with_render(R"({"width": 1e12})"), "render.width", "from 1 to 16384");
  expect_field_error(with_render(R"({"width": 64.5})"), "render.width", "whole number");
  // 16384 x 16384 is 268435456 pixels, four times kMaxImagePixels.
  expect_field_error(with_render(R"({"width": 16384, "height": 16384})"), "render",
                     "268435456 pixels");
  expect_field_error(with_render(R"({"spp": 0})"), "render.spp", "from 1 to 4096");
  expect_field_error(with_render(R"({"spp": 4097})"), "render.spp", "from 1 to 4096");
  expect_field_error(with_render(R"({"seed": -1})"), "render.seed", "from 0 to 4294967295");
}

TEST(SceneLoaderErrors, ImpossibleCamerasAreRefused) {
  expect_field_error(with_camera(R"({"fov_y": 0})"), "camera.fov_y", "between 0 and 180");
  expect_field_error(with_camera(R"({"fov_y": 180})"), "camera.fov_y", "between 0 and 180");
  expect_field_error(with_camera(R"({"eye": [1, 2, 3], "target": [1, 2, 3]})"), "camera.target",
                     "must differ from camera.eye");
  expect_field_error(with_camera(R"({"eye": [0, 5, 0], "target": [0, 0, 0], "up": [0, 2, 0]})"),
                     "camera.up", "parallel");
}

TEST(SceneLoaderErrors, AttenuationMustBeNonNegativeAndNotAllZero) {
  expect_field_error(with_light(R"({"position": [1, 1, 1], "attenuation": [0, 0, 0]})"),
                     "lights[0].attenuation", "not all 0");
  expect_field_error(with_light(R"({"position": [1, 1, 1], "attenuation": [1, -0.5, 0]})"),
                     "lights[0].attenuation[1]", "must be >= 0, got -0.5");
}

TEST(SceneLoaderErrors, ShapeParametersOutOfRangeAreRefused) {
  expect_field_error(with_object(R"({"type": "teapot", "tessellation": 65, "material": "m"})"),
                     "objects[0].tessellation", "from 1 to 64");
  expect_field_error(with_object(R"({"type": "teapot", "scale": [1, 0, 1], "material": "m"})"),
                     "objects[0].scale", "must not be 0");
  expect_field_error(
      with_object(R"({"type": "box", "min": [0, 0, 0], "max": [1, 0, 1], "material": "m"})"),
      "objects[0].max", "greater than min");
  // Checked before the file is read, so the file need not exist.
  expect_field_error(with_object(R"({"type": "mesh", "file": "x.obj", "crease_angle": 180.5})"),
                     "objects[0].crease_angle", "0..180");
  expect_field_error(with_object(R"({"type": "mesh", "file": "x.obj", "crease_angle": -1})"),
                     "objects[0].crease_angle", "0..180");
}

TEST(SceneLoaderErrors, ObjProblemsNameTheObjectAndTheObjFile) {
  ScratchFolder folder;
  std::ofstream(folder.file("garbage.obj")) << "This is not a Wavefront OBJ file.\n";
  std::ofstream(folder.file("range.obj")) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n";
  const std::string scene = folder.file("scene.json");
  auto mesh_error = [&](const std::string& file) {
    std::ofstream(scene) << R"({"objects": [{"type": "mesh", "file": ")" + file + R"("}]})";
    try {
      load_scene(scene);
    } catch (const InputError& error) {
      return error;
    }
    ADD_FAILURE() << file << " accepted";
    return InputError("", "");
  };
  for (const std::string obj : {"missing.obj", "garbage.obj", "range.obj"}) {
    const InputError error = mesh_error(obj);
    const std::string what = error.what();
    EXPECT_EQ(error.field(), "objects[0].file") << what;
    EXPECT_EQ(what.rfind(scene + ": objects[0].file: ", 0), 0u) << what;
    EXPECT_NE(what.find(obj), std::string::npos) << what;
  }
  // The model reader's own message survives after the file's name (assimp's OBJ reader names no
  // line for a bad index; where a reader does, InputError keeps it as file:line).
  EXPECT_NE(
      std::string(mesh_error("range.obj").what()).find("range.obj: OBJ: vertex index out of range"),
      std::string::npos);
}

TEST(SceneLoaderErrors, MissingSceneFileNamesThePath) {
  ScratchFolder folder;
  try {
    load_scene(folder.file("nowhere.json"));
    FAIL() << "missing file accepted";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("nowhere.json"), std::string::npos);
  }
}

// Validation computes in the renderer's float: what passes cannot fail later as "eye and target
// coincide" with no field (docs/spec/scene-and-cli.md, "Numeric limits").
TEST(SceneLoaderErrors, CoordinatesBeyondFloatArithmeticAreRefusedNamingTheField) {
  // 1.85e19 squared overflows a float: the renderer's |target - eye| was infinite.
  expect_field_error(with_camera(R"({"eye": [0, 0, 1.85e19], "target": [0, 0, 0]})"),
                     "camera.eye[2]", "from -1e+15 to 1e+15");
  expect_field_error(with_camera(R"({"eye": [0, 0, 5], "target": [-2e15, 0, 0]})"),
                     "camera.target[0]", "got -2e+15");
  expect_field_error(with_light(R"({"position": [0, 1e16, 0]})"), "lights[0].position[1]",
                     "from -1e+15 to 1e+15");
  expect_field_error(with_object(R"({"type": "sphere", "center": [3e38, 0, 0], "radius": 1,
                                     "material": "m"})"),
                     "objects[0].center[0]", "got 3e+38");
  expect_field_error(with_object(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1e20,
                                     "material": "m"})"),
                     "objects[0].radius", "at most 1e+15");
  expect_field_error(with_object(R"({"type": "box", "min": [0, 0, 0], "max": [1, 1, 2e15],
                                     "material": "m"})"),
                     "objects[0]", "placed vertices reach 2e+15 on axis 2");
}

TEST(SceneLoaderErrors, DistancesThatCollapseInFloatAreRefusedNamingTheField) {
  // 1e-30 apart: distinct floats, but (1e-30)^2 underflows to 0 in float, so the renderer's
  // view direction had no length.
  expect_field_error(with_camera(R"({"eye": [0, 0, 1e-30], "target": [0, 0, 0]})"), "camera.target",
                     "too close for float arithmetic");
  // An up hint of length 1e-30: its cross product with the view direction underflows likewise.
  expect_field_error(with_camera(R"({"eye": [0, 0, 5], "target": [0, 0, 0], "up": [0, 1e-30, 0]})"),
                     "camera.up", "too short for float");
  EXPECT_NO_THROW(
      parse_scene(with_camera(R"({"eye": [0, 0, 1e15], "target": [0, 0, -1e15]})"), "bad.json"));
}

}  // namespace
}  // namespace gloss
