#pragma once
// The Embree 3 scene built from a Scene: every ray-scene query of gloss goes through it.
// Spheres are Embree sphere points; everything else is triangles. geomID == object index.
// Hidden objects are left out (geometry IDs keep the object indices).
// Built with it: the per-primitive table its hits are shaded from (surface_table.h). Objects
// whose material has an opacity map are cut out by filter functions (cut_outs.h).
#include <embree3/rtcore.h>

#include <memory>
#include <vector>

#include "engine/trace/cut_outs.h"
#include "engine/trace/surface_table.h"
#include "scene/scene.h"

namespace gloss {

class EmbreeScene {
 public:
  explicit EmbreeScene(const Scene& scene);  // throws RuntimeFailure on an Embree error
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  RTCScene handle() const { return m_scene; }
  const SurfaceTable& surfaces() const { return m_surfaces; }

 private:
  RTCDevice m_device = nullptr;
  RTCScene m_scene = nullptr;
  SurfaceTable m_surfaces;
  std::vector<std::unique_ptr<CutOut>> m_cut_outs;  // the filters' data, as long as the scene
};

// The Embree device shared by all scenes of the process (created once, thread-safe).
RTCDevice embree_device();

}  // namespace gloss
