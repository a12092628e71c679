// The JSON a .glb holds is read from its JSON chunk alone (the 12-byte header, the chunk's 8-byte
// header, then the chunk's own length): GLB files made here byte by byte from the glTF 2.0
// specification's container layout, and assimp-testmodels' BoxTextured.glb. A JSON chunk longer
// than the file is a one-line error naming the file. Also the OBJ side: `mtllib` lines read line
// by line (CRLF ends, indented statements, a name with spaces).
#include "io/model/gltf_extras.h"

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "base/error.h"
#include "io/model/model_loader.h"
#include "support/scratch_folder.h"

namespace gloss {
namespace {

void put_u32(std::string& out, std::uint32_t x) {
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((x >> (8 * i)) & 0xFFu));
}

// A GLB: header (magic "glTF", version 2, total length), the JSON chunk (padded with spaces to
// 4 bytes), a BIN chunk of bin_bytes zero bytes. json_length, when given, replaces the JSON
// chunk's length field.
std::string glb(std::string json, std::uint32_t bin_bytes, std::int64_t json_length = -1) {
  while (json.size() % 4 != 0) json.push_back(' ');
  std::string out;
  put_u32(out, 0x46546C67u);
  put_u32(out, 2);
  put_u32(out, static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + bin_bytes));
  put_u32(out, json_length >= 0 ? static_cast<std::uint32_t>(json_length)
                                : static_cast<std::uint32_t>(json.size()));
  put_u32(out, 0x4E4F534Au);
  out += json;
  put_u32(out, bin_bytes);
  put_u32(out, 0x004E4942u);  // "BIN\0"
  out.append(bin_bytes, '\0');
  return out;
}

std::string write(const ScratchFolder& folder, const std::string& name, const std::string& bytes) {
  const std::string path = folder.file(name);
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

const char* const kExtras = R"({"asset": {"version": "2.0"}, "materials": [
  {"name": "clay", "extras": {"gloss": {"ambient": [0.1, 0.2, 0.3], "diffuse": [0.5, 0.25, 0.125],
   "specular": [1, 1, 1], "emission": [0, 0, 0], "shininess": 64}}},
  {"name": "plain"}]})";

TEST(GltfExtras, AGlbsJsonChunkIsReadBeforeItsBuffers) {
  const ScratchFolder folder;
  const GltfMaterialExtras extras = read_gloss_extras(write(folder, "m.glb", glb(kExtras, 4096)));
  ASSERT_TRUE(extras.parsed);
  ASSERT_EQ(extras.materials.size(), 2u);
  ASSERT_TRUE(extras.materials[0].has_value());
  EXPECT_EQ(extras.materials[0]->name, "clay");
  EXPECT_EQ(extras.materials[0]->diffuse, glm::vec3(0.5f, 0.25f, 0.125f));
  EXPECT_EQ(extras.materials[0]->shininess, 64.0f);
  EXPECT_FALSE(extras.materials[1].has_value());
}

TEST(GltfExtras, AGltfIsReadWhole) {
  const ScratchFolder folder;
  const GltfMaterialExtras extras = read_gloss_extras(write(folder, "m.gltf", kExtras));
  ASSERT_TRUE(extras.parsed);
  ASSERT_EQ(extras.materials.size(), 2u);
  EXPECT_EQ(extras.materials[0]->ambient, glm::vec3(0.1f, 0.2f, 0.3f));
}

TEST(GltfExtras, AJsonChunkLongerThanTheFileNamesTheFile) {
  const ScratchFolder folder;
  // 12 + 8 + 256 (the JSON, padded) + 8 + 16 = 300 bytes; the chunk claims 1000.
  std::string json = kExtras;
  json.resize(256, ' ');
  const std::string bytes = glb(json, 16, 1000);
  ASSERT_EQ(bytes.size(), 300u);
  const std::string path = write(folder, "long.glb", bytes);
  try {
    read_gloss_extras(path);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              path + ": GLB's JSON chunk of 1000 bytes runs past the end of the file (300 bytes)");
  }
  // The most a 4-byte length can say, past any file here.
  const std::string huge = write(folder, "huge.glb", glb(json, 16, 0xFFFFFFFFu));
  EXPECT_THROW(read_gloss_extras(huge), InputError);
  // Loading the model: one line naming the file (assimp's reader or this one says why).
  try {
    load_model(path);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind(path + ":", 0), 0u) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

TEST(GltfExtras, AGlbCutShortOrWithoutJsonFirstIsAnError) {
  const ScratchFolder folder;
  const std::string bytes = glb(kExtras, 0);
  const std::string short_path = write(folder, "short.glb", bytes.substr(0, 14));
  try {
    read_gloss_extras(short_path);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              short_path + ": GLB cut short: 14 bytes, fewer than its 20-byte header");
  }
  std::string bin_first = bytes;
  bin_first.replace(16, 4, "BIN");
  bin_first[19] = '\0';
  EXPECT_THROW(read_gloss_extras(write(folder, "bin.glb", bin_first)), InputError);
}

TEST(GltfExtras, BoxTexturedGlbHasOneMaterialWithoutGlossExtras) {
  const std::string path = "/usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "assimp-testmodels not installed";
  const GltfMaterialExtras extras = read_gloss_extras(path);
  EXPECT_TRUE(extras.parsed);
  ASSERT_EQ(extras.materials.size(), 1u);
  EXPECT_FALSE(extras.materials[0].has_value());
  // And the model still loads with its embedded base colour map.
  const Model model = load_model(path);
  ASSERT_EQ(model.materials.size(), 1u);
  EXPECT_TRUE(model.materials[0].has_map(MapSlot::diffuse));
}

TEST(ObjMtlLibraries, IndentedCrlfAndSpacedNamesAreFound) {
  const ScratchFolder folder;
  // The MTL names an image that is not there: the warning about it shows that the library was
  // found (by its whole name, spaces and all) and read.
  write(folder, "my parts.mtl", "newmtl red\r\nKd 1 0 0\r\nmap_Kd missing.png\r\n");
  const std::string obj = write(folder, "tri.obj",
                                "  \tmtllib my parts.mtl\r\nv 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\n"
                                "usemtl red\r\nf 1 2 3\r\n");
  const Model model = load_model(obj);
  ASSERT_EQ(model.material_names.size(), 1u);
  ASSERT_EQ(model.unused.size(), 1u);
  EXPECT_EQ(model.unused[0], "material 'red': image 'missing.png' not found; left out");
}

}  // namespace
}  // namespace gloss
