// libFuzzer target: the scene reader (io/scene/scene_loader.h) on arbitrary text. The scene "file"
// sits in a temporary folder next to two small OBJ files (cube.obj, tetra.obj, named in the
// dictionary), so mesh objects reach the model loader too; presets and the teapot come from the
// shipped assets.
#include <cstdint>
#include <string>
#include <vector>

#include "base/error.h"
#include "fuzz_input.h"
#include "io/scene/scene_loader.h"

namespace {

const char* const kCube =
    "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
    "f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 4 8 7\nf 4 7 3\n"
    "f 1 5 8\nf 1 8 4\nf 2 3 7\nf 2 7 6\n";
const char* const kTetra =
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  gloss_fuzz::write_file("cube.obj", kCube);
  gloss_fuzz::write_file("tetra.obj", kTetra);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const std::string path = (gloss_fuzz::temp_dir() / "scene.json").string();
  try {
    std::vector<std::string> warnings;
    const gloss::Scene scene = gloss::parse_scene(text, path, &warnings);
    // What loads must save: the writer's text reads back (issue 11: a scene that loads can
    // always be saved).
    gloss::parse_scene(gloss::scene_to_json_text(scene), path);
  } catch (const gloss::InputError&) {
  }
  return 0;
}
