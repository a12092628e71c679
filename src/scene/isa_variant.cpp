#include "scene/isa_variant.h"

// GLOSS_PIXEL_ISA is set per compilation of this file by src/CMakeLists.txt.
#ifndef GLOSS_PIXEL_ISA
#define GLOSS_PIXEL_ISA "x86-64"
#endif

namespace gloss {

const char* pixel_code_isa() {
  return GLOSS_PIXEL_ISA;
}

}  // namespace gloss
