#pragma once
// The recently opened files shown in File > Open Recent and in the file browser, kept as one
// absolute path per line in the config folder. Scenes, models and material files are separate
// lists (a scene offered by the Add model panel would be loaded as a model with one click).
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

// What was opened: each kind has its own list and file in the config folder.
enum class RecentKind { scene, model, materials, maps };
// "recent.txt" (scenes, the name the list had before models had their own), "recent-models.txt",
// "recent-materials.txt", "recent-maps.txt" (images loaded into a material's map slots).
const char* recent_file_name(RecentKind kind);

struct RecentLists {
  RecentFiles scenes, models, materials, maps;
  RecentFiles& of(RecentKind kind);
  const RecentFiles& of(RecentKind kind) const;
};

// A missing or unreadable file gives an empty list (recent files are a convenience).
RecentFiles load_recent_files(const std::filesystem::path& file);
// Writes atomically; throws RuntimeFailure when the file cannot be written.
void save_recent_files(const RecentFiles& recent, const std::filesystem::path& file);

// Every kind's list from its file in folder.
RecentLists load_recent_lists(const std::filesystem::path& folder);

}  // namespace gloss
