#pragma once
// A PNG written by gloss carries the scene it shows as JSON in a "gloss:scene" text chunk
// (docs/spec/scene-and-cli.md, "Reopening a PNG"), so a screenshot or a render opens again as
// the scene that made it. load_scene (scene_loader.h) hands any file that starts with the PNG
// signature to load_scene_from_png.
#include <string>
#include <vector>

#include "scene/scene.h"

namespace gloss {

// The PNG text keyword that holds the scene.
inline constexpr const char* kSceneChunkKeyword = "gloss:scene";

// True when the file starts with the 8-byte PNG signature; false for a missing or short file.
bool has_png_signature(const std::string& path);

// The scene JSON to embed in a PNG: scene_to_json_text with each relative file name (models,
// maps, the environment) made absolute against the scene's folder (scene_files.h), so the PNG
// reopens from whatever folder it is saved to.
std::string embedded_scene_text(const Scene& scene);

// The scene a gloss PNG carries, read, validated and resolved as load_scene does. The scene has
// no path (it is untitled: saving it asks for a name) and absolute file names. Throws
// InputError naming the PNG: one line when it carries no scene, and for an error inside the
// embedded JSON the PNG plus the place ("shot.png (embedded scene):3:7: ...",
// "shot.png (embedded scene): objects[1].radius: ...").
Scene load_scene_from_png(const std::string& path, std::vector<std::string>* warnings = nullptr,
                          std::vector<std::string>* notes = nullptr);

}  // namespace gloss
