#pragma once
// Tracing adaptive sampling's extra samples (sample_cache.h RefinedSamples): the same packets,
// Embree queries and light factors as a cache plane, over a list of (pixel, stratum) entries
// instead of an image row. A refined pixel's samples lie where uniform sampling with the same
// spp and seed puts them, so a refined pixel equals that pixel of the uniform image.
#include <cstdint>
#include <functional>
#include <vector>

#include "engine/render_context.h"
#include "engine/trace/sample_cache.h"

namespace gloss {

struct SamplePacket;

// Traces spp stratified samples of each of `pixels` (region indices, ascending) into
// cache.refined, replacing what it held. false when cancelled (cache.refined is then empty).
bool trace_refined_samples(SampleCache& cache, const RenderContext& ctx,
                           std::vector<std::uint32_t> pixels, int spp);

// Recomputes the refined samples' light factors (shadow rays included) for the context's scene
// and plan from their cached hits. false when cancelled (the factors are then stale).
bool recompute_refined_light_factors(SampleCache& cache, const RenderContext& ctx);

// Runs visit(packet) -> rays over the refined samples' packets (oneTBB workers), each with its
// entries' directions and cached hits loaded (a packet's lanes are entries of the refined plane,
// lane i entry packet.x0 + i). Adds the rays to ctx.rays; false when cancelled.
bool visit_refined_samples(const SampleCache& cache, const RenderContext& ctx,
                           const std::function<long long(SamplePacket&)>& visit);

}  // namespace gloss
