// libFuzzer target: the editor's crash-recovery file (io/scene/recovery_file.h, parse_recovery),
// read at every start of the editor; what it accepts is written back and read again, as the next
// autosave would.
#include <cstdint>
#include <string>

#include "base/error.h"
#include "fuzz_input.h"
#include "io/scene/recovery_file.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  // Scenes in the recovery file resolve meshes against its folder, as in the scene target.
  gloss_fuzz::write_file("cube.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const std::string path = (gloss_fuzz::temp_dir() / "recovery.json").string();
  try {
    const gloss::Recovery recovery = gloss::parse_recovery(text, path);
    gloss::parse_recovery(gloss::recovery_text(recovery.scene, recovery.selected_object), path);
  } catch (const gloss::InputError&) {
  }
  return 0;
}
