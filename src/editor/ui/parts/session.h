#pragma once
// Files and session: the file panel, the recent files, the unsaved-changes question before
// opening another scene, where the editor keeps its settings, and the crash recovery (autosave,
// and a crashed session's document offered back). The actions that open and save files are
// file_actions.h's.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "editor/model/session/autosave.h"
#include "editor/model/session/recent_files.h"
#include "editor/model/session/unsaved_guard.h"
#include "editor/ui/file_browser.h"

namespace gloss {

struct Session {
  FileBrowser browser;   // the file panel (Open, Save as, Add model ...)
  RecentLists recent;    // scenes, models and material files, each its own list
  UnsavedGuard unsaved;  // the save / discard / cancel question before opening a scene
  std::filesystem::path config_folder;       // layout and recent files (config_paths.h)
  std::optional<Autosaver> autosaver;        // none with --no-recovery or in a plain script run
  std::string autosave_failure_shown;        // the autosave failure already announced as a notice
  std::optional<Recovery> offered_recovery;  // a crashed session's document awaiting an answer
  // The scene read for an open that waits for the unsaved-changes question (unsaved), with the
  // reader's warnings: the file was read before the question was asked.
  std::shared_ptr<const Scene> pending_open;
  std::vector<std::string> pending_warnings;
};

}  // namespace gloss
