// libFuzzer target: a Wavefront OBJ file through the model loader (fuzz_model.h). The input is
// written to model.obj in a temporary folder (the loader takes a path); a fixed materials.mtl
// lies next to it so `mtllib materials.mtl` and `usemtl` reach the material path.
#include <cstdint>
#include <string>

#include "base/error.h"
#include "fuzz_input.h"
#include "fuzz_model.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  gloss_fuzz::write_file("materials.mtl",
                         "newmtl red\nKa 0.1 0 0\nKd 0.8 0.1 0.1\nKs 0.5 0.5 0.5\nNs 32\n"
                         "newmtl white\nKd 0.9 0.9 0.9\n");
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = gloss_fuzz::write_file("model.obj", data, size);
  try {
    gloss_fuzz::load_model_file(path);
  } catch (const gloss::InputError&) {
  }
  return 0;
}
