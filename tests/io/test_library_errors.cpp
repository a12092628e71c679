// Every reader turns the libraries' exceptions into an InputError naming the file and the place
// (docs/spec/scene-and-cli.md: bad input is exit 2 with one line naming the file).
#include <zlib.h>

#include <cstdint>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "base/error.h"
#include "io/image/image_io.h"
#include "io/material/material_io.h"
#include "io/scene/recovery_file.h"
#include "io/scene/scene_loader.h"
#include "support/scratch_folder.h"

namespace gloss {
namespace {

template <class F>
InputError input_error_of(F read) {
  try {
    read();
  } catch (const InputError& error) {
    return error;
  } catch (const std::exception& error) {
    ADD_FAILURE() << "not an InputError: " << error.what();
  }
  ADD_FAILURE() << "nothing thrown";
  return InputError("", "");
}

// 1e400 overflows a double: nlohmann throws out_of_range (406) without a position.
TEST(LibraryErrors, MaterialsJsonNumberOutOfRangeIsAnInputErrorAtTheNumber) {
  ScratchFolder folder;
  const std::string path = folder.file("m.json");
  std::ofstream(path) << "{\"materials\": {\n  \"a\": {\"shininess\": 1e400}\n}}\n";
  const InputError error = input_error_of([&] { load_materials_json(path); });
  EXPECT_EQ(error.file(), path);
  EXPECT_EQ(error.line(), 2);
  EXPECT_EQ(error.column(), 22);  // the '1' of 1e400
  EXPECT_NE(error.message().find("1e400"), std::string::npos) << error.what();
}

TEST(LibraryErrors, SceneNumberOutOfRangeIsAnInputErrorAtTheNumber) {
  const InputError error = input_error_of(
      [] { parse_scene("{\"objects\": [],\n \"ambient\": [1e999, 0, 0]}", "s.json"); });
  EXPECT_EQ(error.file(), "s.json");
  EXPECT_EQ(error.line(), 2);
  EXPECT_EQ(error.column(), 14);
}

TEST(LibraryErrors, RecoveryFileWithWrongTypesIsAnInputError) {
  const std::string scene = R"({"objects": []})";
  const InputError wrong_type = input_error_of([&] {
    parse_recovery(R"({"gloss_recovery": 1, "selected_object": "two", "scene": )" + scene + "}",
                   "r.json");
  });
  EXPECT_EQ(wrong_type.file(), "r.json");
  const InputError version_string = input_error_of(
      [&] { parse_recovery(R"({"gloss_recovery": "1", "scene": )" + scene + "}", "r.json"); });
  EXPECT_EQ(version_string.file(), "r.json");
  const InputError overflow = input_error_of(
      [&] { parse_recovery(R"({"gloss_recovery": 1e999, "scene": )" + scene + "}", "r.json"); });
  EXPECT_EQ(overflow.line(), 1);
}

TEST(LibraryErrors, EmptyOrDuplicateMaterialNamesInAMaterialsFileAreRefusedByTheReader) {
  ScratchFolder folder;
  const std::string path = folder.file("m.json");
  std::ofstream(path) << R"({"materials": {"": {}}})";
  EXPECT_EQ(input_error_of([&] { load_materials_json(path); }).field(), "materials");
  std::ofstream(path) << R"({"materials": {"a\\xE6": {}, "a\\xe6": {}}})";
  EXPECT_NE(input_error_of([&] { load_materials_json(path); }).message().find("duplicate"),
            std::string::npos);
}

void append_chunk(std::string& png, const std::string& type, const std::string& data) {
  const auto be32 = [&](std::uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8) png += static_cast<char>((v >> shift) & 0xFF);
  };
  be32(static_cast<std::uint32_t>(data.size()));
  const std::string body = type + data;
  png += body;
  be32(static_cast<std::uint32_t>(
      crc32(0, reinterpret_cast<const Bytef*>(body.data()), static_cast<uInt>(body.size()))));
}

// A PNG header of 1000000 x 1000000 pixels (libpng's own limit) with a token IDAT: 3e12 bytes of
// RGB, which read_png used to ask of std::vector (std::length_error or bad_alloc, exit 1).
TEST(LibraryErrors, APngHeaderPastThePixelLimitIsAnInputError) {
  ScratchFolder folder;
  std::string png = "\x89PNG\r\n\x1a\n";
  const std::string ihdr("\x00\x0f\x42\x40\x00\x0f\x42\x40\x08\x02\x00\x00\x00", 13);
  append_chunk(png, "IHDR", ihdr);  // 0x0F4240 = 1000000, 8-bit RGB
  append_chunk(png, "IDAT", std::string("\x78\x9c", 2));
  append_chunk(png, "IEND", "");
  std::ofstream(folder.file("huge.png"), std::ios::binary) << png;
  const InputError error = input_error_of([&] { read_png(folder.file("huge.png")); });
  EXPECT_EQ(error.file(), folder.file("huge.png"));
  // libpng refuses the header at gloss's largest image side (16384) before anything is allocated.
  EXPECT_EQ(error.message(),
            "invalid PNG: Invalid IHDR data (Image height exceeds user limit in IHDR)");
}

}  // namespace
}  // namespace gloss
