#include "editor/model/session/autosave.h"

#include <exception>
#include <system_error>

#include "base/atomic_file.h"
#include "editor/model/document/command_layer.h"
#include "editor/model/session/config_paths.h"

namespace gloss {

std::filesystem::path default_recovery_file() {
  return state_dir() / "recovery.json";
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
  const bool retry_due = m_retry_at_s >= 0.0 && now_s >= m_retry_at_s;
  if (m_retry_at_s >= 0.0 ? !retry_due : (!quiet && !overdue)) return false;

  if (!layer.dirty()) {
    discard();
    m_written_revision = m_seen_revision;
    m_first_change_s = m_retry_at_s = -1.0;
    m_failure.clear();
    return false;
  }
  try {
    write_text_atomically(m_file.string(), recovery_text(layer.scene(), selected_object));
  } catch (const std::exception& error) {
    // Any failure (the folder, the disk, a name the writer refused) leaves the edits unprotected:
    // it is reported, not thrown, and the write is tried again.
    m_failure = error.what();
    ++m_failure_count;
    m_retry_at_s = now_s + m_retry_s;
    return false;
  }
  m_written_revision = m_seen_revision;
  m_first_change_s = m_retry_at_s = -1.0;
  m_failure.clear();
  return true;
}

std::string autosave_notice(const Autosaver& autosaver) {
  if (autosaver.failure().empty()) return {};
  return "AUTOSAVE FAILING (a crash would lose the edits): " + autosaver.failure();
}

void Autosaver::discard() {
  std::error_code ignored;  // nothing to remove is fine
  std::filesystem::remove(m_file, ignored);
}

}  // namespace gloss
