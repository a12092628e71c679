#pragma once
// The raster path's vertex buffers: each mesh object's world-space triangles (Object::mesh, the
// tessellation the ray tracer uses) and the cube every sphere impostor is drawn with. A Mesh is
// immutable and shared (scene.h), so its buffer is keyed by the Mesh and uploaded once; an edit
// that re-tessellates makes a new Mesh and a new buffer, and buffers no object uses any more are
// freed at the next sync().
#include <cstddef>
#include <map>
#include <memory>

#include <glad/gl.h>

#include "scene/scene.h"

namespace gloss {

struct MeshBuffer {
  GLuint vertex_array = 0, buffer = 0;
  GLsizei vertices = 0;       // 3 per triangle
  int floats_per_vertex = 9;  // 46 with the maps' attributes (raster_geometry.cpp)
};

class RasterGeometry {
 public:
  RasterGeometry();  // needs a current GL context
  ~RasterGeometry();
  RasterGeometry(const RasterGeometry&) = delete;
  RasterGeometry& operator=(const RasterGeometry&) = delete;

  // Uploads the meshes of scene not uploaded yet and frees those it no longer has; returns the
  // number of meshes uploaded.
  int sync(const Scene& scene);
  // The buffer of a mesh of the scene last synced.
  const MeshBuffer& mesh(const Mesh& mesh) const;
  // The impostor cube: 36 vertices of [-1, 1]^3 at attribute 0, drawn as GL_TRIANGLES.
  GLuint cube() const { return m_cube_array; }
  // Bytes of vertex data held (the editor's `memory` line).
  std::size_t bytes() const;

 private:
  struct Entry {
    std::shared_ptr<const Mesh> mesh;  // keeps the key's address from being reused
    MeshBuffer buffer;
  };
  std::map<const Mesh*, Entry> m_meshes;
  GLuint m_cube_array = 0, m_cube_buffer = 0;
};

}  // namespace gloss
