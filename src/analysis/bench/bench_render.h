#pragma once
// The engine's passes as the benchmarks time them (analysis's own: engine types).
#include "engine/shade/pixel_factors.h"
#include "engine/trace/embree_scene.h"
#include "engine/trace/sample_cache.h"
#include "scene/scene.h"

namespace gloss {

// A full 1-spp render through the engine's stages, BVH already built: trace, light factors (the
// environment's fast path among them), per-pixel factors and the total image in one fused pass,
// as the engine's first full-resolution pass; with terms, the four term images by recombination
// after it.
void full_render(const Scene& scene, const EmbreeScene& embree, SampleCache& cache,
                 PixelFactors& factors, TermImages& out, bool terms);

}  // namespace gloss
