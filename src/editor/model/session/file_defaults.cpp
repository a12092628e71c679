#include "editor/model/session/file_defaults.h"

#include <algorithm>
#include <fstream>
#include <system_error>

#include "base/assets.h"
#include "base/atomic_file.h"
#include "editor/model/session/config_paths.h"

namespace gloss {

namespace {

namespace fs = std::filesystem;

// Absolute, normalised and with links resolved where the path exists.
fs::path canonical_or_normal(const fs::path& path) {
  std::error_code ec;
  const fs::path resolved = fs::weakly_canonical(fs::absolute(path, ec), ec);
  return ec ? fs::absolute(path, ec).lexically_normal() : resolved;
}

bool is_within(const fs::path& path, const fs::path& folder) {
  const fs::path relative = path.lexically_relative(folder);
  return !relative.empty() && *relative.begin() != "..";
}

bool is_folder(const fs::path& path) {
  std::error_code ec;
  return !path.empty() && fs::is_directory(path, ec);
}

}  // namespace

bool is_shipped_path(const std::string& path) {
  if (path.empty()) return false;
  return is_within(canonical_or_normal(path), canonical_or_normal(asset_dir()));
}

std::string shipped_scene_refusal(const std::string& path) {
  if (!is_shipped_path(path)) return "";
  return path + " is a scene gloss ships: save it under another name";
}

fs::path save_folder(const fs::path& last) {
  if (is_folder(last) && !is_shipped_path(last.string())) return last;
  return documents_dir();
}

fs::path open_folder(const fs::path& last, const std::string& scene_path) {
  if (is_folder(last)) return last;
  const fs::path scene_dir = fs::path(scene_path).parent_path();
  if (!scene_path.empty() && is_folder(scene_dir)) return scene_dir;
  return documents_dir();
}

std::string file_name_for(const std::string& name, const std::string& extension) {
  std::string out;
  for (const char c : name) {
    const auto u = static_cast<unsigned char>(c);
    const bool bad =
        u < 0x20 || u == 0x7f || std::string("/\\:*?\"<>|").find(c) != std::string::npos;
    out += bad ? '-' : c;
  }
  const std::size_t first = out.find_first_not_of(" .-");
  out = first == std::string::npos ? std::string() : out.substr(first);
  while (!out.empty() && (out.back() == ' ' || out.back() == '.')) out.pop_back();
  return (out.empty() ? std::string("untitled") : out) + extension;
}

std::string scene_file_name(const std::string& scene_path) {
  return scene_path.empty() ? std::string("untitled.json")
                            : fs::path(scene_path).filename().string();
}

std::string suggested_file_name(const Scene& scene, int object, const std::string& what) {
  if (what == "save-scene") return scene_file_name(scene.path);
  if (what == "save-materials") {
    const std::string stem = scene.path.empty() ? "scene" : fs::path(scene.path).stem().string();
    return file_name_for(stem + " materials", ".json");
  }
  if (what != "save-material" && what != "export-glsl") return "";
  std::string material = "material";
  if (!scene.objects.empty()) {
    const int i = std::clamp(object, 0, static_cast<int>(scene.objects.size()) - 1);
    const int m = scene.objects[static_cast<std::size_t>(i)].material;
    if (m >= 0 && m < static_cast<int>(scene.material_names.size())) {
      material = scene.material_names[static_cast<std::size_t>(m)];
    }
  }
  return file_name_for(material, what == "export-glsl" ? ".frag" : ".json");
}

fs::path load_last_folder(const fs::path& config_folder) {
  std::ifstream in(config_folder / "last-folder.txt");
  std::string line;
  std::getline(in, line);
  return line;
}

void save_last_folder(const fs::path& config_folder, const fs::path& folder) {
  try {
    write_text_atomically((config_folder / "last-folder.txt").string(), folder.string() + "\n");
  } catch (const std::exception&) {
    // Like the recent files: a convenience that must not stop a save.
  }
}

}  // namespace gloss
