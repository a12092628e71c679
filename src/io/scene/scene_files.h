#pragma once
// The files a scene names: its objects' model files, its materials' maps (for a map made from or
// held in a model, MODEL#MATERIAL/SLOT, the MODEL part) and its environment map. A relative name
// is relative to the scene file's folder (docs/scene-format.md), so every place that moves a
// scene to another folder (Save As, a script's `save`, a PNG that carries the scene) renames
// them all here, one way.
#include <string>

#include "scene/scene.h"

namespace gloss {

// Renames every relative file the scene names, from the folder of scene.path to the folder of
// new_path (relative again, as the contract has a saved scene name its maps; absolute only where
// no relative name exists), then sets scene.path to new_path. Absolute names stay.
void rebase_scene_files(Scene& scene, const std::string& new_path);

// How a scene at scene_path names `file` (any path, relative to the current folder or absolute):
// relative to the scene's folder, or absolute where no relative name exists; an untitled scene
// (scene_path "") names it relative to the current folder, as the loader then reads it.
std::string name_for_scene(const std::string& file, const std::string& scene_path);

// Makes every relative file the scene names absolute against `folder` (the current folder when
// empty): for a scene carried by a PNG, which may be copied anywhere.
void make_scene_files_absolute(Scene& scene, const std::string& folder);

}  // namespace gloss
