#include "autosave.h"

#include <ctime>
#include <system_error>

#include <nlohmann/json.hpp>

#include "atomic_file.h"
#include "command_layer.h"
#include "config_paths.h"
#include "error.h"
#include "scene_loader.h"

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

std::filesystem::path default_recovery_file() {
  return state_dir() / "recovery.json";
}

std::string recovery_text(const Scene& scene, int selected_object) {
  nlohmann::json j;
  j["gloss_recovery"] = kRecoveryVersion;
  j["saved_at"] = local_time_text();
  j["scene_path"] = scene.path;
  j["selected_object"] = selected_object;
  j["scene"] = nlohmann::json::parse(scene_to_json_text(scene));
  return j.dump(2) + "\n";
}

Recovery parse_recovery(const std::string& text, const std::string& file) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(file, std::string("not a recovery file: ") + e.what());
  }
  if (!j.is_object() || j.value("gloss_recovery", 0) != kRecoveryVersion || !j.contains("scene") ||
      !j["scene"].is_object()) {
    throw InputError(
        file, "not a gloss recovery file (version " + std::to_string(kRecoveryVersion) + ")");
  }
  Recovery recovery;
  const std::string scene_path = j.value("scene_path", std::string());
  // The scene's relative paths (meshes) resolve against the file the session had open.
  recovery.scene = parse_scene(j["scene"].dump(), scene_path.empty() ? file : scene_path);
  recovery.scene.path = scene_path;
  recovery.selected_object = j.value("selected_object", -1);
  recovery.saved_at = j.value("saved_at", std::string());
  return recovery;
}

std::optional<Recovery> read_recovery(const std::filesystem::path& file) {
  std::error_code error;
  if (!std::filesystem::exists(file, error)) return std::nullopt;
  return parse_recovery(read_text_file(file.string()), file.string());
}

Autosaver::Autosaver(std::filesystem::path file, std::uint64_t start_revision, double quiet_s,
                     double max_delay_s)
    : m_file(std::move(file)),
      m_quiet_s(quiet_s),
      m_max_delay_s(max_delay_s),
      m_written_revision(start_revision),
      m_seen_revision(start_revision) {}

bool Autosaver::step(const CommandLayer& layer, int selected_object, double now_s) {
  if (layer.revision() != m_seen_revision) {
    m_seen_revision = layer.revision();
    m_last_change_s = now_s;
    if (m_first_change_s < 0.0) m_first_change_s = now_s;
  }
  if (m_written_revision == m_seen_revision) return false;
  const bool quiet = now_s - m_last_change_s >= m_quiet_s;
  const bool overdue = m_first_change_s >= 0.0 && now_s - m_first_change_s >= m_max_delay_s;
  if (!quiet && !overdue) return false;

  m_written_revision = m_seen_revision;
  m_first_change_s = -1.0;
  if (!layer.dirty()) {
    discard();
    return false;
  }
  write_text_atomically(m_file.string(), recovery_text(layer.scene(), selected_object));
  return true;
}

void Autosaver::discard() {
  std::error_code ignored;  // nothing to remove is fine
  std::filesystem::remove(m_file, ignored);
}

}  // namespace gloss
