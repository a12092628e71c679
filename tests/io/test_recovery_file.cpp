// The crash-recovery file's own fields (io/scene/recovery_file.h): the selected object is a whole
// number that fits an int, checked before any conversion; the scene inside is the scene reader's.
#include "io/scene/recovery_file.h"

#include <string>

#include <gtest/gtest.h>

#include "base/error.h"

namespace gloss {
namespace {

// A recovery file around a one-sphere scene, with selected_object's JSON text as given.
std::string recovery_with_selection(const std::string& selected) {
  return R"({"gloss_recovery": 1, "saved_at": "2026-11-25 11:00:00", "scene_path": "",
  "selected_object": )" +
         selected + R"(, "scene": {
  "camera": {"eye": [0, 0, 5], "target": [0, 0, 0], "up": [0, 1, 0], "fov_y": 40},
  "lights": [{"position": [2, 2, 2]}],
  "materials": {"m": {"diffuse": [0.5, 0.5, 0.5]}},
  "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"}]}})";
}

TEST(RecoveryFile, SelectedObjectIsReadAsWritten) {
  EXPECT_EQ(parse_recovery(recovery_with_selection("0"), "r.json").selected_object, 0);
  EXPECT_EQ(parse_recovery(recovery_with_selection("-1"), "r.json").selected_object, -1);
  EXPECT_EQ(parse_recovery(recovery_with_selection("2147483647"), "r.json").selected_object,
            2147483647);
}

// Found while writing fuzz/fuzz_recovery: 1e300 went through nlohmann's unchecked double-to-int
// conversion (undefined behaviour; UBSan: "1e+300 is outside the range of representable values
// of type 'int'"). Out-of-range and non-whole values are now InputErrors naming the field.
TEST(RecoveryFile, SelectedObjectOutsideAnIntIsAnInputErrorNamingTheField) {
  for (const char* selected : {"1e300", "-1e300", "2147483648", "-2", "0.5", "\"1\""}) {
    try {
      parse_recovery(recovery_with_selection(selected), "r.json");
      ADD_FAILURE() << "selected_object " << selected << " was accepted";
    } catch (const InputError& error) {
      EXPECT_EQ(error.file(), "r.json");
      EXPECT_EQ(error.field(), "selected_object") << error.what();
    }
  }
}

// Found by fuzz/fuzz_recovery: a version of 1.7e72 went through the same unchecked conversion.
// Any version other than 1 is not a recovery file.
TEST(RecoveryFile, AVersionOtherThanOneIsNotARecoveryFile) {
  const std::string good = recovery_with_selection("0");
  for (const char* version : {"1.7e72", "-1e300", "2", "1.5", "\"1\""}) {
    std::string text = good;
    text.replace(text.find("\"gloss_recovery\": 1"), 19,
                 std::string("\"gloss_recovery\": ") + version);
    try {
      parse_recovery(text, "r.json");
      ADD_FAILURE() << "version " << version << " was accepted";
    } catch (const InputError& error) {
      EXPECT_NE(std::string(error.what()).find("not a gloss recovery file"), std::string::npos)
          << error.what();
    }
  }
}

}  // namespace
}  // namespace gloss
