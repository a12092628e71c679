// The pixel code a process runs is the variant it was meant to run: each per-level CTest entry
// of a GLOSS_ISA_VARIANTS build (tests/CMakeLists.txt) names the level it forces in
// GLOSS_EXPECT_ISA, and the loader must have picked that library.
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "scene/isa_variant.h"

namespace gloss {
namespace {

TEST(IsaVariant, TheLoadedPixelCodeIsTheLevelAskedFor) {
  const char* expected = std::getenv("GLOSS_EXPECT_ISA");
  if (expected == nullptr) GTEST_SKIP() << "no level asked for (not a per-level test entry)";
  EXPECT_EQ(std::string(pixel_code_isa()), expected);
}

TEST(IsaVariant, NamesAnX86Level) {
  const std::string isa = pixel_code_isa();
  EXPECT_TRUE(isa == "native" || isa.rfind("x86-64", 0) == 0) << isa;
}

}  // namespace
}  // namespace gloss
