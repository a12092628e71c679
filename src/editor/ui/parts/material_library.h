#pragma once
// The materials offered for applying to the selected object: the preset table's swatches and the
// materials loaded from a file (File > Load materials). The Material panel shows them; applying
// one is a command.
#include <string>
#include <vector>

#include "editor/ui/panels/swatches.h"
#include "io/material/material_io.h"

namespace gloss {

struct MaterialLibrary {
  Swatches swatches;                  // one rendered ball per preset (preset_table() order)
  std::vector<NamedMaterial> loaded;  // materials loaded from a file, applied on demand
  std::string loaded_from;            // that file's name
};

}  // namespace gloss
