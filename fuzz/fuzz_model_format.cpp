// libFuzzer target: a model file of one format through the model loader (fuzz_model.h), the
// format fixed at build time by GLOSS_FUZZ_EXTENSION (".ply", ".stl", ".glb"): assimp picks its
// reader from the extension, so one binary per format keeps each fuzzer on one reader. glTF's
// binary form is fuzzed (.glb): the text form is JSON with external buffers, which the
// scene_json target's JSON paths and the .glb container both cover poorly, so .gltf seeds go to
// the glb target's corpus only as what they are, JSON in a .glb (assimp then refuses them).
#include <cstdint>
#include <string>

#include "base/error.h"
#include "fuzz_input.h"
#include "fuzz_model.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path =
      gloss_fuzz::write_file(std::string("model") + GLOSS_FUZZ_EXTENSION, data, size);
  try {
    gloss_fuzz::load_model_file(path);
  } catch (const gloss::InputError&) {
  }
  return 0;
}
