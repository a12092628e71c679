#include "editor/model/session/recent_files.h"

#include <algorithm>
#include <fstream>

#include "base/atomic_file.h"

namespace gloss {

void RecentFiles::add(const std::string& path) {
  std::error_code ignored;
  std::string absolute = std::filesystem::absolute(path, ignored).lexically_normal().string();
  if (absolute.empty()) absolute = path;
  paths.erase(std::remove(paths.begin(), paths.end(), absolute), paths.end());
  paths.insert(paths.begin(), absolute);
  if (paths.size() > kMaxCount) paths.resize(kMaxCount);
}

RecentFiles load_recent_files(const std::filesystem::path& file) {
  RecentFiles recent;
  std::ifstream in(file);
  for (std::string line; std::getline(in, line) && recent.paths.size() < RecentFiles::kMaxCount;) {
    if (!line.empty() &&
        std::find(recent.paths.begin(), recent.paths.end(), line) == recent.paths.end()) {
      recent.paths.push_back(line);
    }
  }
  return recent;
}

void save_recent_files(const RecentFiles& recent, const std::filesystem::path& file) {
  std::string text;
  for (const std::string& path : recent.paths) text += path + "\n";
  write_text_atomically(file.string(), text);
}

const char* recent_file_name(RecentKind kind) {
  switch (kind) {
    case RecentKind::scene:
      return "recent.txt";
    case RecentKind::model:
      return "recent-models.txt";
    case RecentKind::materials:
      return "recent-materials.txt";
    case RecentKind::maps:
      return "recent-maps.txt";
  }
  return "recent.txt";
}

RecentFiles& RecentLists::of(RecentKind kind) {
  switch (kind) {
    case RecentKind::model:
      return models;
    case RecentKind::materials:
      return materials;
    case RecentKind::maps:
      return maps;
    case RecentKind::scene:
      break;
  }
  return scenes;
}

const RecentFiles& RecentLists::of(RecentKind kind) const {
  return const_cast<RecentLists*>(this)->of(kind);
}

RecentLists load_recent_lists(const std::filesystem::path& folder) {
  RecentLists lists;
  for (RecentKind kind :
       {RecentKind::scene, RecentKind::model, RecentKind::materials, RecentKind::maps}) {
    lists.of(kind) = load_recent_files(folder / recent_file_name(kind));
  }
  return lists;
}

}  // namespace gloss
