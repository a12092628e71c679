#pragma once
// The editor's crash-recovery file: the scene as scene_to_json_text writes it, plus the path of
// the file the session had open, the selection and when it was written.
#include <filesystem>
#include <optional>
#include <string>

#include "scene/scene.h"

namespace gloss {

struct Recovery {
  Scene scene;  // scene.path is the file the session had open ("" when none)
  int selected_object = -1;
  std::string saved_at;  // local time, "YYYY-MM-DD HH:MM:SS"
};

// The file's text, and the text read back; parse_recovery throws InputError naming file for
// anything it cannot read back.
std::string recovery_text(const Scene& scene, int selected_object);
Recovery parse_recovery(const std::string& text, const std::string& file);

// nullopt when there is no file; throws InputError for a damaged one.
std::optional<Recovery> read_recovery(const std::filesystem::path& file);

}  // namespace gloss
