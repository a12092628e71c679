#pragma once
// The model loader the OBJ, MTL and model-format targets call, in one place:
// io/model/model_loader.h's load_model, the one import path (assimp) of every model format.
#include <string>

#include "io/model/model_loader.h"

namespace gloss_fuzz {

inline void load_model_file(const std::string& path) {
  (void)gloss::load_model(path);
}

}  // namespace gloss_fuzz
