#pragma once
// The materials offered for applying to the selected object: the preset table's swatches, the
// user's library folder (its materials as swatches beside the presets) and the materials loaded
// from a file (File > Load materials); and the swatches of the scene's materials for the
// material list. The Material panel shows them; applying one is a command.
#include <filesystem>
#include <string>
#include <vector>

#include "editor/model/session/material_library_folder.h"
#include "editor/ui/panels/material_swatches.h"
#include "editor/ui/panels/swatches.h"
#include "io/material/material_io.h"

namespace gloss {

struct MaterialLibrary {
  Swatches swatches;                  // one rendered ball per preset (preset_table() order)
  MaterialSwatches balls;             // the scene's and the user library's materials, on demand
  std::filesystem::path folder;       // the user's library (material_library_folder.h)
  std::vector<LibraryMaterial> user;  // its materials, read at start and after each save
  std::vector<NamedMaterial> loaded;  // materials loaded from a file, applied on demand
  std::string loaded_from;            // that file's name
};

}  // namespace gloss
