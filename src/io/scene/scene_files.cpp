#include "io/scene/scene_files.h"

#include <filesystem>
#include <functional>

#include "io/model/model_maps.h"

namespace gloss {

namespace {

namespace fs = std::filesystem;

// Calls rename(file) on each file name of the scene that rename may change: an object's file
// (a model's), a plain map's file or a model map's MODEL part, the environment's file.
void for_each_scene_file(Scene& scene, const std::function<void(std::string&)>& rename) {
  for (Object& object : scene.objects) {
    if (!object.params.file.empty()) rename(object.params.file);
  }
  rename_map_files(scene.materials, [&](std::string& name, bool) { rename(name); });
  if (!scene.environment.file.empty()) rename(scene.environment.file);
}

// The folder names are relative to, absolute: the current folder for "" (an untitled scene's
// relative names are relative to it, as the loader resolves them).
fs::path absolute_of(fs::path folder) {
  if (folder.empty()) folder = ".";
  std::error_code ec;
  fs::path absolute = (fs::absolute(folder, ec)).lexically_normal();
  if (ec) return folder.lexically_normal();
  // "/a/b/." normalises to "/a/b/": without the trailing separator it compares equal to "/a/b".
  if (!absolute.has_filename() && absolute.has_relative_path()) absolute = absolute.parent_path();
  return absolute;
}

}  // namespace

void rebase_scene_files(Scene& scene, const std::string& new_path) {
  const fs::path from = absolute_of(fs::path(scene.path).parent_path());
  const fs::path to = absolute_of(fs::path(new_path).parent_path());
  if (from != to) {
    for_each_scene_file(scene, [&](std::string& file) {
      const fs::path name(file);
      if (name.is_absolute()) return;
      const fs::path target = (from / name).lexically_normal();
      const fs::path relative = target.lexically_relative(to);
      file = relative.empty() ? target.generic_string() : relative.generic_string();
    });
  }
  scene.path = new_path;
}

std::string name_for_scene(const std::string& file, const std::string& scene_path) {
  const fs::path target = absolute_of(fs::path(file).parent_path()) / fs::path(file).filename();
  const fs::path relative =
      target.lexically_relative(absolute_of(fs::path(scene_path).parent_path()));
  return relative.empty() ? target.generic_string() : relative.generic_string();
}

void make_scene_files_absolute(Scene& scene, const std::string& folder) {
  const fs::path base = absolute_of(folder);
  for_each_scene_file(scene, [&](std::string& file) {
    const fs::path name(file);
    if (!name.is_absolute()) file = (base / name).lexically_normal().generic_string();
  });
}

}  // namespace gloss
