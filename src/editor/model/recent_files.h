#pragma once
// The recently opened files shown in File > Open Recent and in the file browser, kept as one
// absolute path per line in the config folder.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace gloss {

struct RecentFiles {
  std::vector<std::string> paths;  // newest first, no duplicates
  static constexpr std::size_t kMaxCount = 12;

  // Moves path (made absolute) to the front, dropping the oldest past kMaxCount.
  void add(const std::string& path);
};

// A missing or unreadable file gives an empty list (recent files are a convenience).
RecentFiles load_recent_files(const std::filesystem::path& file);
// Writes atomically; throws RuntimeFailure when the file cannot be written.
void save_recent_files(const RecentFiles& recent, const std::filesystem::path& file);

}  // namespace gloss
