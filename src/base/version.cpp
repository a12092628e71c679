#include "base/version.h"

namespace gloss {

const char* gloss_version() {
  return GLOSS_VERSION;  // defined for this file by src/base/CMakeLists.txt
}

}  // namespace gloss
