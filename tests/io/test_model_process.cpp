// The model import runs in a child process (io/model/model_process.h): what the child makes comes
// back bit for bit, its InputErrors come back as they were, and a child that crashes or dies is a
// clean InputError naming the file, with this process unharmed.
#include "io/model/model_process.h"

#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "base/error.h"

namespace gloss {
namespace {

InputError error_of(const std::function<Model(const std::string&)>& import) {
  try {
    import_in_child_process("model.glb", import);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError";
  return InputError("", "");
}

TEST(ModelProcess, TheChildsModelComesBackBitForBit) {
  Model sent;
  ModelPart part;
  part.material_name = std::string("Terrain\xE6k", 8);  // names are bytes
  part.mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1e-38f, 3.5f}};
  part.mesh.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0.6f, 0.8f}};
  part.mesh.triangles = {{0, 1, 2}};
  sent.parts = {part, ModelPart{}};
  Material m;
  m.diffuse = {0.1f, 0.2f, 0.3f};
  m.shininess = 1e6f;
  m.preset = "gold";
  sent.material_names = {"a", "b"};
  sent.materials = {m, Material{}};
  sent.warnings = {"dropped 2 degenerate triangles"};
  const Model got = import_in_child_process("x.obj", [&](const std::string&) { return sent; });
  ASSERT_EQ(got.parts.size(), 2u);
  EXPECT_EQ(got.parts[0].material_name, part.material_name);
  EXPECT_EQ(got.parts[0].mesh.positions, part.mesh.positions);
  EXPECT_EQ(got.parts[0].mesh.normals, part.mesh.normals);
  EXPECT_EQ(got.parts[0].mesh.triangles, part.mesh.triangles);
  EXPECT_TRUE(got.parts[1].mesh.positions.empty());
  EXPECT_EQ(got.material_names, sent.material_names);
  ASSERT_EQ(got.materials.size(), 2u);
  EXPECT_EQ(got.materials[0], m);
  EXPECT_EQ(got.materials[0].preset, "gold");
  EXPECT_EQ(got.warnings, sent.warnings);
}

TEST(ModelProcess, AnInputErrorOfTheChildComesBackWithItsPlace) {
  const InputError e = error_of([](const std::string&) -> Model {
    throw InputError("m.obj", "vertex index out of range", 12, 3, "f");
  });
  EXPECT_EQ(e.file(), "m.obj");
  EXPECT_EQ(e.message(), "vertex index out of range");
  EXPECT_EQ(e.line(), 12);
  EXPECT_EQ(e.column(), 3);
  EXPECT_EQ(e.field(), "f");
}

TEST(ModelProcess, ACrashInTheLibraryIsAnInputErrorNamingTheFile) {
  const InputError e = error_of([](const std::string&) -> Model {
    std::raise(SIGSEGV);  // what assimp does on some fuzzed glTF and MTL files
    return {};
  });
  EXPECT_EQ(e.file(), "model.glb");
  EXPECT_NE(e.message().find("the model library failed on this file (crashed with signal 11"),
            std::string::npos)
      << e.message();
}

TEST(ModelProcess, AChildThatExitsOrRunsOutOfMemoryIsAnInputError) {
  EXPECT_NE(error_of([](const std::string&) -> Model { std::_Exit(0); })
                .message()
                .find("failed on this file"),
            std::string::npos);
  EXPECT_NE(error_of([](const std::string&) -> Model { throw std::bad_alloc(); })
                .message()
                .find("ran out of memory"),
            std::string::npos);
}

// A 100-byte PLY header found by fuzz_ply keeps assimp busy for ever: the child is killed at
// the limit (1 s here) and the file refused, naming the variable that sets the limit.
TEST(ModelProcess, AnImportPastTheTimeLimitIsKilledAndRefused) {
  setenv(kImportTimeVariable, "1", 1);
  const auto start = std::chrono::steady_clock::now();
  const InputError e = error_of([](const std::string&) -> Model {
    for (;;) pause();
  });
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  unsetenv(kImportTimeVariable);
  EXPECT_EQ(e.message(),
            "the model library did not finish reading this file in 1 s "
            "(GLOSS_IMPORT_TIME_LIMIT_S sets the limit)");
  EXPECT_GE(seconds, 0.9) << "returned before the limit";  // a bound, not a speed claim
}

}  // namespace
}  // namespace gloss
