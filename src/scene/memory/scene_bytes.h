#pragma once
// What a Scene value holds in memory, for the editor's undo history (which keeps copies of the
// document) and its memory report. Meshes are held by shared_ptr<const Mesh> and copies of a
// scene share them, so they are counted apart: a copy costs scene_bytes_without_meshes, and a
// mesh costs mesh_bytes once, however many copies point at it.
#include <cstdint>

#include "scene/scene.h"

namespace gloss {

// Bytes of the mesh's arrays (capacity, not size: what the allocator gave them).
std::uint64_t mesh_bytes(const Mesh& mesh);

// Bytes of the scene's own storage: the struct, its vectors' capacity and the heap buffers of
// its strings (strings short enough for the in-place buffer cost nothing more). Meshes excluded.
std::uint64_t scene_bytes_without_meshes(const Scene& scene);

// Bytes of the meshes of `held` that `other` does not also point at (each counted once): what
// keeping `held` alive costs beside `other`.
std::uint64_t unshared_mesh_bytes(const Scene& held, const Scene& other);

}  // namespace gloss
