#pragma once
// The model loader the OBJ and MTL targets call, in one place: today io/obj_loader.h's load_obj;
// when the assimp-based loader replaces it, only this wrapper changes.
#include <string>

#include "io/obj_loader.h"

namespace gloss_fuzz {

inline void load_model_file(const std::string& path) {
  (void)gloss::load_obj(path, true);
}

}  // namespace gloss_fuzz
