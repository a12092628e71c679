#pragma once
// The app's file and session actions: opening a scene (asking about unsaved changes first),
// adding a model, saving the scene, loading and saving materials, exporting a GLSL shader,
// recovering a crashed session, quitting. Unlike panels these replace or re-file the whole
// document, so they hold the command layer itself. Each throws InputError / RuntimeFailure with
// a message for the UI; on failure the document is unchanged.
#include <memory>
#include <string>
#include <vector>

#include "editor/model/document/command_layer.h"
#include "editor/model/session/recent_files.h"

namespace gloss {

class Commands;
struct MaterialLibrary;
struct OpenWindows;
struct RunState;
struct Selection;
struct Session;

class FileActions {
 public:
  FileActions(CommandLayer& document, Commands& commands, Selection& selection, Session& session,
              MaterialLibrary& library, OpenWindows& windows, RunState& run)
      : m_document(document),
        m_commands(commands),
        m_selection(selection),
        m_session(session),
        m_library(library),
        m_windows(windows),
        m_run(run) {}

  void open_scene(const std::string& path);
  // Opens path, first asking save / discard / cancel when the document has unsaved changes (the
  // question is a modal; scripts never ask). Throws as open_scene when it opens at once.
  // The file is read first: one that cannot be read is refused (an InputError) before anything
  // is asked, and the scene read is the one opened.
  void request_open_scene(const std::string& path);
  void add_model(const std::string& path);
  void save_scene_as(const std::string& path);
  void load_materials(const std::string& path);
  // Every material of the scene, or the selected object's alone (issue 24: "save the selected
  // material, not every material").
  void save_materials(const std::string& path);
  void save_selected_material(const std::string& path);
  // Saves the selected object's material into the user's library folder
  // (material_library_folder.h) and reads the library again.
  void save_to_library();
  void reload_library();
  // Writes the selected object's material as a GLSL fragment shader
  // (editor/model/export/glsl_export.h).
  void export_glsl_shader(const std::string& path);
  // The scene as glTF; the notice (status bar) gives each material's fit and its error.
  void export_gltf_scene(const std::string& path);
  // Reads the image at path into the map slot of object's material (keeping the slot's wrap,
  // scale and offset), as one command; throws InputError naming the file when it cannot be read.
  void load_map(int object, MapSlot slot, const std::string& path);
  // Runs the file browser's chosen action, keeping the browser open with the error on failure.
  void browser_action(const std::string& path);
  void remember_recent(RecentKind kind, const std::string& path);
  // Replaces the document with the offered recovery (session.offered_recovery), or declines it.
  void recover();
  void discard_recovery();
  // Opens a scene already read (request_open_scene's, or the one that waited for the question).
  void open_loaded(std::shared_ptr<const Scene> scene, const std::string& path,
                   const std::vector<std::string>& warnings);
  // Quits, first asking about unsaved changes (OpenWindows::quit_question; scripts never ask).
  void request_quit();

 private:
  CommandLayer& m_document;
  Commands& m_commands;
  Selection& m_selection;
  Session& m_session;
  MaterialLibrary& m_library;
  OpenWindows& m_windows;
  RunState& m_run;
};

}  // namespace gloss
