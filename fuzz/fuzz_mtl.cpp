// libFuzzer target: a Wavefront MTL file, two ways: gloss's own MTL reader
// (io/material/material_io.h, load_mtl, the editor's material import) with what it accepts written
// back and read again, and the model loader (fuzz_model.h) on a fixed OBJ that names the fuzzed
// file as its mtllib.
#include <cstdint>
#include <string>

#include "base/error.h"
#include "fuzz_input.h"
#include "fuzz_model.h"
#include "io/material/material_io.h"

namespace {

// A quad in two parts, each with a material the dictionary's MTL snippets define.
const char* const kObj =
    "mtllib fuzzed.mtl\n"
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\n"
    "usemtl red\nf 1//1 2//1 3//1\n"
    "usemtl white\nf 1//1 3//1 4//1\n";

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  gloss_fuzz::write_file("model.obj", kObj);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = gloss_fuzz::write_file("fuzzed.mtl", data, size);
  try {
    const auto materials = gloss::load_mtl(path);
    const std::string again = (gloss_fuzz::temp_dir() / "again.mtl").string();
    gloss::save_mtl(again, materials);
    gloss::load_mtl(again);
  } catch (const gloss::InputError&) {
  }
  try {
    gloss_fuzz::load_model_file((gloss_fuzz::temp_dir() / "model.obj").string());
  } catch (const gloss::InputError&) {
  }
  return 0;
}
