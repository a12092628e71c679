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

// What update_refined_samples did, in pixels.
struct RefinedUpdate {
  std::size_t kept = 0, traced = 0, dropped = 0;
};

// Moves cache.refined (spp > 0) to the placement `pixels` (region indices, ascending) at the same
// spp: the samples of pixels refined before are kept (their hits, and their light factors unless
// lights_stale, when they get shadow rays from the kept hits), newly refined pixels are traced,
// and pixels no longer refined are dropped. The samples equal trace_refined_samples' for the
// same placement. spare: a plane whose memory the new samples take; it receives the plane no
// longer in use. false when cancelled (cache.refined is then as it was). counts, when given,
// receives what was kept, traced and dropped.
bool update_refined_samples(SampleCache& cache, const RenderContext& ctx,
                            std::vector<std::uint32_t> pixels, bool lights_stale,
                            SamplePlane& spare, RefinedUpdate* counts = nullptr);

// Recomputes the refined samples' light factors (shadow rays included) for the context's scene
// and plan from their cached hits. false when cancelled (the factors are then stale).
bool recompute_refined_light_factors(SampleCache& cache, const RenderContext& ctx);

// Runs visit(packet) -> rays over the refined samples' packets (oneTBB workers), each with its
// entries' directions and cached hits loaded (a packet's lanes are entries of the refined plane,
// lane i entry packet.x0 + i). Adds the rays to ctx.rays; false when cancelled.
bool visit_refined_samples(const SampleCache& cache, const RenderContext& ctx,
                           const std::function<long long(SamplePacket&)>& visit);

}  // namespace gloss
