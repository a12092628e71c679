#include "io/scene/recovery_file.h"

#include <ctime>
#include <limits>
#include <system_error>

#include <nlohmann/json.hpp>

#include "base/atomic_file.h"
#include "base/error.h"
#include "io/json/json_location.h"
#include "io/json/name_escape.h"
#include "io/scene/scene_json_reader.h"
#include "io/scene/scene_loader.h"

namespace gloss {

namespace {

constexpr int kRecoveryVersion = 1;

std::string local_time_text() {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  localtime_r(&now, &tm);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%d %H:%M:%S", &tm);
  return text;
}

}  // namespace

std::string recovery_text(const Scene& scene, int selected_object) {
  nlohmann::json j;
  j["gloss_recovery"] = kRecoveryVersion;
  j["saved_at"] = local_time_text();
  j["scene_path"] = escape_name(scene.path);
  j["selected_object"] = selected_object;
  j["scene"] = nlohmann::json::parse(scene_to_json_text(scene));
  return j.dump(2) + "\n";
}

Recovery parse_recovery(const std::string& text, const std::string& file) {
  const nlohmann::json j = parse_json_text(text, file);
  const auto version = j.is_object() ? j.find("gloss_recovery") : j.end();
  if (!j.is_object() || version == j.end() || *version != kRecoveryVersion ||
      !j.contains("scene") || !j["scene"].is_object()) {
    throw InputError(
        file, "not a gloss recovery file (version " + std::to_string(kRecoveryVersion) + ")");
  }
  Recovery recovery;
  std::string scene_path;
  try {
    scene_path = unescape_name(j.value("scene_path", std::string()));
    recovery.saved_at = j.value("saved_at", std::string());
  } catch (const nlohmann::json::exception& error) {
    // A value of the wrong type (type_error 302) names no field; these two are the only ones.
    throw InputError(
        file, std::string("scene_path or saved_at has the wrong type (") + error.what() + ")");
  }
  // The scene's relative paths (meshes) resolve against the file the session had open.
  recovery.scene = parse_scene(j["scene"].dump(), scene_path.empty() ? file : scene_path);
  recovery.scene.path = scene_path;
  // Checked before converting: nlohmann converts 1e300 to int unchecked (undefined behaviour;
  // found by fuzz/fuzz_recovery).
  const auto selected = j.find("selected_object");
  recovery.selected_object =
      selected == j.end()
          ? -1
          : static_cast<int>(json_integer(*selected, -1, std::numeric_limits<int>::max(), file,
                                          "selected_object"));
  return recovery;
}

std::optional<Recovery> read_recovery(const std::filesystem::path& file) {
  std::error_code error;
  if (!std::filesystem::exists(file, error)) return std::nullopt;
  return parse_recovery(read_text_file(file.string()), file.string());
}

}  // namespace gloss
