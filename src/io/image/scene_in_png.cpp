#include "io/image/scene_in_png.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "base/error.h"
#include "io/image/image_io.h"
#include "io/scene/scene_files.h"
#include "io/scene/scene_loader.h"

namespace gloss {

bool has_png_signature(const std::string& path) {
  static const unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"),
                                                       &std::fclose);
  if (!file) return false;
  unsigned char head[8] = {};
  if (std::fread(head, 1, sizeof head, file.get()) != sizeof head) return false;
  return std::equal(head, head + 8, kSignature);
}

std::string embedded_scene_text(const Scene& scene) {
  Scene copy = scene;
  make_scene_files_absolute(copy, std::filesystem::path(scene.path).parent_path().string());
  return scene_to_json_text(copy);
}

Scene load_scene_from_png(const std::string& path, std::vector<std::string>* warnings,
                          std::vector<std::string>* notes) {
  const Png8 png = read_png(path);
  const std::string* text = nullptr;
  for (const auto& [keyword, value] : png.text) {
    if (keyword == kSceneChunkKeyword) text = &value;
  }
  if (text == nullptr) {
    throw InputError(path, std::string("this PNG carries no scene (no '") + kSceneChunkKeyword +
                               "' text); only PNGs written by gloss or gloss-cli reopen as scenes");
  }
  // The label names the PNG and what inside it is meant; its folder is the PNG's, so a relative
  // file name (from a PNG written before names were made absolute) resolves beside the PNG.
  Scene scene = parse_scene(*text, path + " (embedded scene)", warnings, notes);
  make_scene_files_absolute(scene, std::filesystem::path(path).parent_path().string());
  scene.path.clear();
  return scene;
}

}  // namespace gloss
