#include "editor/model/recent_files.h"

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

}  // namespace gloss
