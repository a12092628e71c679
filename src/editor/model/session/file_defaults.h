#pragma once
// Where the file panel starts and what it suggests (issue 24, item 3): Save as and exports never
// start on a shipped file or in the install's assets, but in the user's own last folder (the
// folder of the last file they chose, kept between sessions) or their documents folder, with a
// name taken from the scene or the material. Opening may start anywhere readable.
#include <filesystem>
#include <string>

#include "scene/scene.h"

namespace gloss {

// Whether path lies in the shipped assets (base/assets.h's asset_dir(): the source tree's
// assets/ or an install's share/gloss/assets): a file gloss ships, never overwritten.
bool is_shipped_path(const std::string& path);

// The reason a save to path is refused ("" when it is not a file gloss ships): every way of
// saving a scene (the panels, the questions before quitting or opening, scripts) asks it.
std::string shipped_scene_refusal(const std::string& path);

// Whether a scene at path may be saved where it is (Save, Ctrl+Shift+S, "Save and quit", "Save,
// then open"): it has a file and the file is not one gloss ships. Otherwise only Save as.
inline bool saves_in_place(const std::string& path) {
  return !path.empty() && !is_shipped_path(path);
}

// The folder a save or an export starts in: last (the folder of the user's last chosen file)
// when it is a folder and not shipped, else documents_dir() (config_paths.h).
std::filesystem::path save_folder(const std::filesystem::path& last);

// The folder Open, Add model and Load materials start in: last when it is a folder, else the
// scene's folder when it has a file, else documents_dir().
std::filesystem::path open_folder(const std::filesystem::path& last, const std::string& scene_path);

// name made a file name: characters that a file name cannot hold or that shells make awkward
// ('/', '\\', ':', '*', '?', '"', '<', '>', '|', control bytes) become '-', spaces stay; "untitled"
// when nothing is left; then the extension (with its dot).
std::string file_name_for(const std::string& name, const std::string& extension);

// The name Save as suggests: the scene file's name ("spheres.json") or "untitled.json".
std::string scene_file_name(const std::string& scene_path);

// The name the file panel suggests for what (a `browse` word: "save-scene", "save-material",
// "save-materials", "export-glsl"; "" for the others): the scene's file name, the selected
// object's material's name (.json, .frag), "<scene stem> materials.json".
std::string suggested_file_name(const Scene& scene, int object, const std::string& what);

// The last folder kept in folder/last-folder.txt; empty when there is none.
std::filesystem::path load_last_folder(const std::filesystem::path& config_folder);
// Keeps it (atomically); a failure to write is ignored (a convenience, like recent files).
void save_last_folder(const std::filesystem::path& config_folder,
                      const std::filesystem::path& folder);

}  // namespace gloss
