// The session's questions, as modals: recover a crashed session's document, quit with unsaved
// changes, open another scene over unsaved changes (UnsavedGuard's rules). Scripts never see them.
#include <filesystem>
#include <optional>

#include <imgui.h>

#include "editor/model/session/file_defaults.h"
#include "editor/ui/panels/panels.h"
#include "editor/ui/parts/commands.h"
#include "editor/ui/parts/file_actions.h"
#include "editor/ui/parts/open_windows.h"
#include "editor/ui/parts/run_state.h"
#include "editor/ui/parts/session.h"

namespace gloss {

namespace {
// Why a question offers no "save" answer: the scene has no file, or its file is one gloss ships.
void save_as_hint(const std::string& path) {
  ImGui::TextDisabled(path.empty() ? "(untitled: use Save scene as... first to keep them)"
                                   : "(a scene gloss ships: use Save scene as... first to keep "
                                     "them)");
}
}  // namespace

void draw_recovery_modal(const Session& session, FileActions& files) {
  if (!session.offered_recovery) return;
  const char* id = "Recover unsaved session?";
  if (!ImGui::IsPopupOpen(id)) ImGui::OpenPopup(id);
  if (!ImGui::BeginPopupModal(id, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  const Recovery& r = *session.offered_recovery;
  ImGui::TextUnformatted("gloss did not exit cleanly last time.");
  ImGui::Text("An autosaved session from %s is available", r.saved_at.c_str());
  ImGui::Text("(scene: %s).", r.scene.path.empty() ? "not saved to a file" : r.scene.path.c_str());
  ImGui::Separator();
  if (ImGui::Button("Recover", ImVec2(140, 0))) {
    files.recover();
    ImGui::CloseCurrentPopup();
  }
  ImGui::SameLine();
  if (ImGui::Button("Discard", ImVec2(140, 0))) {
    files.discard_recovery();
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

void draw_quit_modal(OpenWindows& windows, Commands& commands, FileActions& files, RunState& run) {
  if (!windows.quit_question) return;
  const char* id = "Unsaved changes";
  if (!ImGui::IsPopupOpen(id)) ImGui::OpenPopup(id);
  if (!ImGui::BeginPopupModal(id, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  const std::string& path = commands.scene().path;
  ImGui::TextUnformatted("The scene has changes that are not saved.");
  // Never over a file gloss ships (it was: Save and quit rewrote assets/scenes/spheres.json).
  const bool in_place = saves_in_place(path);
  if (!in_place) save_as_hint(path);
  if (in_place && ImGui::Button("Save and quit", ImVec2(150, 0))) {
    try {
      files.save_scene_as(path);
      run.quit = true;
    } catch (const std::exception& e) {
      commands.error(e.what());
    }
    windows.quit_question = false;
    ImGui::CloseCurrentPopup();
  }
  if (in_place) ImGui::SameLine();
  if (ImGui::Button("Quit without saving", ImVec2(150, 0))) {
    run.quit = true;
    windows.quit_question = false;
    ImGui::CloseCurrentPopup();
  }
  ImGui::SameLine();
  if (ImGui::Button("Cancel", ImVec2(150, 0))) {
    windows.quit_question = false;
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

void draw_open_modal(Session& session, Commands& commands, FileActions& files) {
  if (!session.unsaved.asking()) return;
  const char* id = "Open another scene";
  if (!ImGui::IsPopupOpen(id)) ImGui::OpenPopup(id);
  if (!ImGui::BeginPopupModal(id, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  const std::string& path = commands.scene().path;
  ImGui::TextUnformatted("The scene has changes that are not saved.");
  ImGui::Text("Open %s anyway?",
              std::filesystem::path(session.unsaved.waiting_path()).filename().string().c_str());
  const bool in_place = saves_in_place(path);
  if (!in_place) save_as_hint(path);
  std::optional<UnsavedAnswer> answer;
  if (in_place && ImGui::Button("Save, then open", ImVec2(150, 0))) {
    answer = UnsavedAnswer::save;
  }
  if (in_place) ImGui::SameLine();
  if (ImGui::Button("Discard changes", ImVec2(150, 0))) answer = UnsavedAnswer::discard;
  ImGui::SameLine();
  if (ImGui::Button("Cancel", ImVec2(150, 0)) ||
      ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) {
    answer = UnsavedAnswer::cancel;
  }
  if (answer) {
    ImGui::CloseCurrentPopup();
    const UnsavedGuard::Outcome outcome = session.unsaved.answer(*answer);
    try {
      if (outcome.save_first) files.save_scene_as(path);
      // The scene read before the question (FileActions::request_open_scene).
      if (outcome.open && session.pending_open) {
        files.open_loaded(session.pending_open, outcome.path, session.pending_warnings);
      }
    } catch (const std::exception& e) {
      commands.error(e.what());
    }
    session.pending_open.reset();
    session.pending_warnings.clear();
  }
  ImGui::EndPopup();
}

}  // namespace gloss
