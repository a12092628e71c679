#pragma once
// The environment's exact terms in the progressive renderer (docs/engine.md, "The
// environment"): per cached sample, running sums of the self-normalised estimates of
// environment_sampling.h, each step three directions (cosine, lobe, map) with the balance
// heuristic and, with shadows on, a shadow ray each (16 lanes to a packet). After each pass
// the environment's slots hold the estimates instead of the fast path's values; the usual
// stages (pixel factors, recombination) make the image from them. No primary ray is traced.
#include <cstdint>
#include <vector>

#include "engine/render_context.h"
#include "engine/trace/sample_cache.h"

namespace gloss {

// Per cached sample 8 floats: the diffuse term's sums (x per channel, y) then the specular's.
struct EnvironmentEstimates {
  static constexpr int kFloats = 8;
  int steps = 0;  // steps every cached sample has taken (0: the slots hold the fast path)
  std::vector<std::vector<float>> planes;  // per plane, kFloats per sample
  std::vector<float> refined;              // per refined entry

  void reset() {
    steps = 0;
    planes.clear();
    refined.clear();
  }
  std::uint64_t bytes() const;
};

// Adds `steps` steps to every cached sample's estimates (sizing them for the cache first) and
// writes the estimates into the environment's slots. false when cancelled: the slots and sums
// are then inconsistent (the caller redoes the environment class and resets).
bool add_environment_steps(SampleCache& cache, const RenderContext& ctx,
                           EnvironmentEstimates& estimates, int steps);

// The next pass's steps towards the scene's env_samples: 16 first (fewer would look noisier
// than the fast path they replace), then doubling; 0 when done or not planned.
int next_environment_steps(const RenderContext& ctx, const EnvironmentEstimates& estimates);

}  // namespace gloss
