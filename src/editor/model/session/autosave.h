#pragma once
// Crash recovery: while the document has unsaved edits it is written (atomically) to a recovery
// file in the state folder; a clean exit removes the file, so a file found at start-up means the
// last session ended without saving, and the editor offers it back.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "io/scene/recovery_file.h"
#include "scene/scene.h"

namespace gloss {

class CommandLayer;

// state_dir()/recovery.json.
std::filesystem::path default_recovery_file();

class Autosaver {
 public:
  // start_revision: the layer's revision when the session began (not written until it changes).
  Autosaver(std::filesystem::path file, std::uint64_t start_revision, double quiet_s = 1.0,
            double max_delay_s = 10.0);

  // Call once per frame. Writes when the document changed since the last write and either
  // quiet_s seconds passed without a change or max_delay_s since the first unwritten change.
  // A document equal to its saved file needs no recovery: the file is removed instead. Returns
  // true after a write. A write that fails throws nothing: failure() says why until a later
  // write succeeds, and the write is tried again every retry_s seconds.
  bool step(const CommandLayer& layer, int selected_object, double now_s);

  // Why the last write failed ("cannot write FILE: REASON", "disk full writing FILE"); empty
  // when it succeeded or none was needed yet. The editor shows it on screen while it is set:
  // edits made meanwhile would be lost in a crash.
  const std::string& failure() const { return m_failure; }
  // Counts failed writes, so the editor can notice a new failure (one notice per failure).
  int failure_count() const { return m_failure_count; }

  // Removes the recovery file (clean exit, or the user declined the offer).
  void discard();

  const std::filesystem::path& file() const { return m_file; }

 private:
  std::filesystem::path m_file;
  double m_quiet_s, m_max_delay_s;
  std::uint64_t m_written_revision;  // revision the file (or its absence) matches
  std::uint64_t m_seen_revision;
  double m_first_change_s = -1.0;  // time of the first change not yet written, -1 when none
  double m_last_change_s = 0.0;
  double m_retry_s = 5.0;      // after a failed write
  double m_retry_at_s = -1.0;  // next try after a failure, -1 when none failed
  std::string m_failure;
  int m_failure_count = 0;
};

// The line the editor keeps on screen while autosave fails, empty while it works.
std::string autosave_notice(const Autosaver& autosaver);

}  // namespace gloss
