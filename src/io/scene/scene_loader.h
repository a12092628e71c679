#pragma once
// Scene JSON (docs/spec/scene-and-cli.md) to Scene and back. Every error is an InputError naming
// the file and the line:column (syntax) or the field path such as objects[2].radius (meaning).
#include <string>
#include <vector>

#include "scene/fields/validation.h"
#include "scene/scene.h"

namespace gloss {

// Reads, validates and resolves (presets, meshes, teapot) a scene file. Warnings (such as
// dropped degenerate triangles) are appended to *warnings when given; notes (how a model's glTF
// materials were read: each as the fitted Phong or by assimp's rule, with both errors), each
// prefixed with the file and the object's field, to *notes.
Scene load_scene(const std::string& path, std::vector<std::string>* warnings = nullptr,
                 std::vector<std::string>* notes = nullptr);

// The same from text; path is used for messages and relative file resolution.
Scene parse_scene(const std::string& text, const std::string& path,
                  std::vector<std::string>* warnings = nullptr,
                  std::vector<std::string>* notes = nullptr);

// The scene as JSON text that parse_scene reads back to an equal scene. save_scene writes it
// atomically.
std::string scene_to_json_text(const Scene& scene);

// The scene with every teapot tessellated at level (1..64), rebuilt through the scene reader so
// placement and degenerate-triangle handling stay the loader's; render settings are kept.
Scene with_teapot_tessellation(const Scene& scene, int level);

// A teapot object's world-space triangles from its params (tessellation, smooth, scale,
// rotate_y, position), as the scene reader makes them (defined in scene_object_reader.cpp), for
// edits that re-tessellate one teapot in place. Degenerate triangles are dropped, unreported.
Mesh teapot_mesh(const ShapeParams& params);
void save_scene(const Scene& scene, const std::string& path);

}  // namespace gloss
