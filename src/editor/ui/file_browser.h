#pragma once
// Dear ImGui 1.86 has no file dialog: this panel lists a folder through std::filesystem, offers
// the recent files, and takes a typed path. The caller performs the open or save; when that
// fails it puts the message in 'error' and the panel stays open with the document untouched.
#include <filesystem>
#include <string>
#include <vector>

#include "editor/model/session/recent_files.h"
#include "scene/texture_map.h"

namespace gloss {

enum class BrowsePurpose {
  open_scene,
  add_model,
  load_materials,
  save_scene,
  save_materials,    // every material of the scene
  save_material,     // the selected object's material alone
  export_glsl,       // issue 12: the selected object's material as a fragment shader
  open_environment,  // an environment map (HDR, EXR, PNG)
  load_map,          // an image into a map slot of a material (map_target says which)
  export_gltf,       // issue 26: the scene as glTF 2.0 (.gltf, .glb)
};
// The recent list the panel offers for purpose (scenes for scenes, models for Add model, ...).
RecentKind recent_kind(BrowsePurpose purpose);
const char* title(BrowsePurpose purpose);
bool is_save(BrowsePurpose purpose);
// Extensions listed (lowercase, with the dot); the first is added to a typed save name without one.
std::vector<std::string> extensions(BrowsePurpose purpose);
// The folder the panel opens in: the scene file's, or fallback (the screenshot folder) for a scene
// without a file.
std::filesystem::path scene_folder(const std::string& scene_path, const std::string& fallback);

struct FileBrowser {
  struct Entry {
    std::string name;
    bool folder = false;
  };

  bool open = false;
  BrowsePurpose purpose = BrowsePurpose::open_scene;
  std::filesystem::path folder;
  std::string name;             // the path field: a name inside folder, or a full path
  std::string error;            // set by the caller when the chosen file failed
  std::string confirm_replace;  // a save target that exists and awaits a second click
  bool show_all = false;        // list files of every extension
  std::vector<Entry> entries;
  bool stale = true;        // entries need re-reading
  bool focus_name = false;  // put the keyboard in the path field on the next draw
  // For load_map: the object whose material gets the image, and the slot.
  struct MapTarget {
    int object = 0;
    MapSlot slot = MapSlot::diffuse;
  } map_target;

  // The folder of the last file the user chose here (kept between sessions by FileActions): where
  // the next panel starts (editor/model/session/file_defaults.h).
  std::filesystem::path last_folder;

  void show(BrowsePurpose what, const std::filesystem::path& start_folder,
            const std::string& suggested_name);
  // Opens the panel where it should start for what: a save or an export in the user's last
  // folder (never in the shipped assets) or the documents folder, an open in the last folder or
  // the scene's; suggested_name in the path field.
  void start(BrowsePurpose what, const std::string& scene_path, const std::string& suggested_name);
  // Draws the panel. Returns true and sets chosen when the user confirmed a path.
  bool draw(const RecentFiles& recent, std::string& chosen);

 private:
  void refresh();
  std::string resolved() const;
  bool confirm(std::string& chosen);
};

}  // namespace gloss
