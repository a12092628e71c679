// Work that would not fit is refused before it is allocated, naming the object or the render
// settings, the estimate and the budget (docs/spec/scene-and-cli.md, "Memory budget").
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "base/error.h"
#include "base/memory_budget.h"
#include "io/scene/scene_loader.h"

namespace gloss {
namespace {

// Sets GLOSS_MEMORY_BUDGET_MB for one test.
class BudgetOf {
 public:
  explicit BudgetOf(const char* mb) { ::setenv(kMemoryBudgetVariable, mb, 1); }
  ~BudgetOf() { ::unsetenv(kMemoryBudgetVariable); }
};

std::string teapots(int count, int level, const std::string& render = "{}") {
  std::string objects;
  for (int i = 0; i < count; ++i) {
    objects += std::string(i ? ", " : "") + R"({"type": "teapot", "tessellation": )" +
               std::to_string(level) + R"(, "material": "m"})";
  }
  return R"({"materials": {"m": {}}, "objects": [)" + objects + R"(], "render": )" + render + "}";
}

InputError error_of(const std::string& text) {
  try {
    parse_scene(text, "big.json");
  } catch (const InputError& error) {
    return error;
  }
  ADD_FAILURE() << "accepted";
  return InputError("", "");
}

TEST(MemoryBudget, ComesFromTheEnvironmentInMegabytes) {
  BudgetOf budget("300");
  EXPECT_EQ(memory_budget_bytes(), 300u * 1024 * 1024);
  EXPECT_EQ(memory_budget_text(), "300 MB (GLOSS_MEMORY_BUDGET_MB)");
}

TEST(MemoryBudget, DefaultsToHalfThePhysicalMemoryWhenUnsetOrInvalid) {
  BudgetOf budget("lots");
  const std::uint64_t half = static_cast<std::uint64_t>(::sysconf(_SC_PHYS_PAGES)) *
                             static_cast<std::uint64_t>(::sysconf(_SC_PAGESIZE)) / 2;
  EXPECT_EQ(memory_budget_bytes(), half);
}

// A teapot at tessellation 64 is 32 * 2 * 64^2 = 262144 triangles, 262144 * 200 bytes = 50 MB:
// two fill a 100 MB budget exactly, the third passes it and is refused before it is tessellated.
TEST(MemoryBudget, TheTeapotThatPassesTheBudgetIsNamed) {
  BudgetOf budget("100");
  const InputError error = error_of(teapots(1000, 64));
  EXPECT_EQ(error.field(), "objects[2]");
  EXPECT_STREQ(error.what(),
               "big.json: objects[2]: teapot, tessellation 64, 262144 triangles: the scene needs "
               "~150 MB with it, budget 100 MB (GLOSS_MEMORY_BUDGET_MB)");
}

// The teapots are counted before any object is read (or tessellated): the budget is the first
// error even though objects[0] is itself wrong.
TEST(MemoryBudget, TeapotsAreCountedBeforeAnyObjectIsRead) {
  BudgetOf budget("100");
  std::string text = teapots(3, 64);
  text.replace(text.find("[{"), 2, R"([{"type": "spher"}, {)");
  const InputError error = error_of(text);
  EXPECT_EQ(error.field(), "objects[3]") << error.what();
}

TEST(MemoryBudget, SmallScenesPass) {
  BudgetOf budget("100");
  EXPECT_NO_THROW(parse_scene(teapots(1, 64), "big.json"));  // ~50 MB and a 16x16-ish image
}

// 16384 x 4096 pixels at 4096 spp with no light, as gloss-cli renders it: one sample row is
// 16384 * 4096 * (20 + 16) = 2415919104 bytes, so bands are the minimum 4 rows, 9216 MB, and
// the pixels 2^26 * 40 bytes = 2560 MB: 11776 MB in all.
TEST(MemoryBudget, RenderSettingsThatPassTheBudgetAreNamed) {
  BudgetOf budget("10000");
  const InputError error =
      error_of(teapots(0, 1, R"({"width": 16384, "height": 4096, "spp": 4096})"));
  EXPECT_EQ(error.field(), "render");
  EXPECT_NE(std::string(error.what())
                .find("16384x4096 at 4096 spp with 0 light(s) needs ~11776 MB besides ~0 MB of "
                      "geometry, budget 10000 MB (GLOSS_MEMORY_BUDGET_MB)"),
            std::string::npos)
      << error.what();
}

// The editor's progressive renderer holds every sample of the image: 1024x1024 at 512 spp with
// one light is 2^20 * 512 * 36 bytes = 18432 MB of samples (+ 48 MB of pixels), while
// gloss-cli's bands of 14 rows (256 MiB / (1024 * 512 * 36) bytes) need 252 MB + 48 MB.
TEST(MemoryBudget, TheEditorCountsEverySampleGlossCliABand) {
  BudgetOf budget("10000");
  const Scene scene = parse_scene(R"({"lights": [{"position": [0, 5, 0]}], "objects": [],
                                      "render": {"width": 1024, "height": 1024, "spp": 512}})",
                                  "big.json");
  EXPECT_NO_THROW(validate_scene(scene, SampleMemory::banded));
  try {
    validate_scene(scene, SampleMemory::whole_image);
    ADD_FAILURE() << "accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.field(), "render");
    EXPECT_NE(std::string(error.what()).find("needs ~18480 MB"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace gloss
