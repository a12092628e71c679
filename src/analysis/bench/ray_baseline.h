#pragma once
// Baselines the benchmark measures the renderer against, in the same process: the bare Embree
// cost of the rays a render traces, and the bare memory cost of the bytes a re-shade streams.
#include <cstddef>
#include <vector>

#include "engine/trace/embree_scene.h"
#include "scene/scene.h"

namespace gloss {

// Traces the primary rays of a width x height, 1-spp image of scene.camera and, for every hit,
// one shadow ray per light with non-black diffuse or specular (when shadows are on), in the same
// 16-ray packets and bands of rows as the renderer, with no shading and no output. Returns the ray
// count.
long long trace_rays_raw(const Scene& scene, const EmbreeScene& embree, int width, int height);

// One parallel streaming pass that reads read_bytes and writes write_bytes (float arrays, one
// add per element): the floor under any re-shade that moves the same bytes. The constructor
// allocates and touches the memory; run() is what to time.
class StreamingPass {
 public:
  StreamingPass(std::size_t read_bytes, std::size_t write_bytes);
  void run();
  float checksum() const { return m_out.empty() ? 0.0f : m_out[m_out.size() / 2]; }

 private:
  std::vector<float> m_in, m_out;
};

}  // namespace gloss
