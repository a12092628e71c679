// libFuzzer target: the materials JSON reader (io/material/material_io.h, load_materials_json), and
// what it accepts written back as JSON and as MTL and read again (names and values must survive).
#include <cstdint>
#include <string>

#include "base/error.h"
#include "fuzz_input.h"
#include "io/material/material_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = gloss_fuzz::write_file("materials.json", data, size);
  try {
    const auto materials = gloss::load_materials_json(path);
    const std::string again = (gloss_fuzz::temp_dir() / "again.json").string();
    gloss::save_materials_json(again, materials);
    gloss::load_materials_json(again);
  } catch (const gloss::InputError&) {
  }
  return 0;
}
