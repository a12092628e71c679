#pragma once
// The Embree 3 scene built from a Scene: every ray-scene query of gloss goes through it.
// Spheres are Embree sphere points; everything else is triangles. geomID == object index.
// Built with it: the per-primitive table its hits are shaded from (surface_table.h).
#include <embree3/rtcore.h>

#include "scene.h"
#include "surface_table.h"

namespace gloss {

class EmbreeScene {
 public:
  explicit EmbreeScene(const Scene& scene);  // throws RuntimeFailure on an Embree error
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  RTCScene handle() const { return m_scene; }
  // World-space extent of all geometry (for ray offsets that scale with the scene).
  float scene_extent() const { return m_extent; }
  const SurfaceTable& surfaces() const { return m_surfaces; }

 private:
  RTCDevice m_device = nullptr;
  RTCScene m_scene = nullptr;
  float m_extent = 1.0f;
  SurfaceTable m_surfaces;
};

// The Embree device shared by all scenes of the process (created once, thread-safe).
RTCDevice embree_device();

}  // namespace gloss
