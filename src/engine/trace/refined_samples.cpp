#include "engine/trace/refined_samples.h"

#include <algorithm>
#include <cstdint>

#include "engine/parallel_loops.h"
#include "engine/trace/sample_packet.h"
#include "shading/sampling.h"

namespace gloss {

namespace {
// Packets per parallel chunk: 64 x 16 entries, enough work to amortise a task.
constexpr int kPacketsPerChunk = 64;

// A packet over entries [e0, e1) of the refined plane: lanes are entries, the plane one row
// (y0 = 0), so the lane stores of sample_packet.h write entry e0 + i.
SamplePacket entry_packet(std::size_t e0, std::size_t e1) {
  return SamplePacket(static_cast<int>(e0), 0, static_cast<int>(e1), 1);
}

// Directions of the packet's entries: sample (entry mod spp) of pixel pixels[entry / spp].
void entry_directions(SamplePacket& packet, const SampleCache& cache,
                      const SamplePattern& pattern) {
  const RefinedSamples& refined = cache.refined;
  // Lane pixels and strata by increments (no division per lane; stride < count); masked-off
  // lanes repeat the last entry, a finite direction nobody reads.
  alignas(64) int lane_x[kLanes], lane_row[kLanes], lane_stratum[kLanes];
  std::size_t k = static_cast<std::size_t>(packet.x0 / refined.spp);
  int s = packet.x0 % refined.spp;
  int stratum = sample_stratum(pattern, s);
  int x = 0, row = 0;
  std::size_t pixel_of_xy = SIZE_MAX;
  for (int i = 0; i < kLanes; ++i) {
    if (k != pixel_of_xy) {
      const std::uint32_t pixel = refined.pixels[k];
      x = static_cast<int>(pixel % static_cast<std::uint32_t>(cache.width));
      row = static_cast<int>(pixel / static_cast<std::uint32_t>(cache.width)) + cache.row0;
      pixel_of_xy = k;
    }
    lane_x[i] = x;
    lane_row[i] = row;
    lane_stratum[i] = stratum;
    if (packet.x0 + i + 1 >= packet.x1) continue;
    stratum += pattern.stride;  // sample_stratum of s + 1
    if (stratum >= pattern.count) stratum -= pattern.count;
    if (++s == refined.spp) {
      s = 0;
      stratum = 0;
      ++k;
    }
  }
  SampleOffset offset[kLanes];
  sample_offsets(pattern, lane_stratum, lane_x, lane_row, kLanes, offset);
  alignas(64) double px[kLanes], py[kLanes];
  for (int i = 0; i < kLanes; ++i) {
    px[i] = static_cast<double>(lane_x[i]) + static_cast<double>(offset[i].dx);
    py[i] = static_cast<double>(lane_row[i]) + static_cast<double>(offset[i].dy);
  }
  packet_directions_at(packet, cache, px, py);
}

// Runs f(packet) -> rays over the refined entries' packets on oneTBB workers; adds the rays to
// ctx.rays. false when cancelled.
template <class F>
bool for_each_entry_packet(const SampleCache& cache, const RenderContext& ctx, F&& f) {
  const std::size_t entries = cache.refined.entries();
  const std::size_t per_chunk = static_cast<std::size_t>(kPacketsPerChunk) * kLanes;
  const int chunks = static_cast<int>((entries + per_chunk - 1) / per_chunk);
  return parallel_chunks(chunks, ctx.cancel, [&](int chunk) {
    long long rays = 0;
    const std::size_t end = std::min(entries, (static_cast<std::size_t>(chunk) + 1) * per_chunk);
    for (std::size_t e = static_cast<std::size_t>(chunk) * per_chunk; e < end; e += kLanes) {
      SamplePacket packet = entry_packet(e, std::min(e + kLanes, end));
      rays += f(packet);
    }
    finish_streaming_stores();
    if (ctx.rays != nullptr) ctx.rays->fetch_add(rays, std::memory_order_relaxed);
  });
}

void no_consumer(std::size_t, const LightLanes&) {}
}  // namespace

bool trace_refined_samples(SampleCache& cache, const RenderContext& ctx,
                           std::vector<std::uint32_t> pixels, int spp) {
  RefinedSamples& refined = cache.refined;
  refined.spp = spp;
  refined.pixels = std::move(pixels);
  size_plane(refined.plane, refined.entries(), ctx.plan.plane_shape());
  const SamplePattern pattern = make_sample_pattern(cache.seed, spp);
  const int width = static_cast<int>(refined.entries());
  const bool done = for_each_entry_packet(cache, ctx, [&](SamplePacket& packet) {
    entry_directions(packet, cache, pattern);
    const long long rays = trace_primary(packet, cache, ctx);
    store_hits(packet, width, refined.plane);
    return rays + shade_sample(packet, cache, ctx, refined.plane, no_consumer);
  });
  if (!done) {
    refined.spp = 0;
    refined.pixels.clear();
  }
  return done;
}

bool recompute_refined_light_factors(SampleCache& cache, const RenderContext& ctx) {
  RefinedSamples& refined = cache.refined;
  if (refined.spp == 0) return true;
  size_plane(refined.plane, refined.entries(), ctx.plan.plane_shape());
  const SamplePattern pattern = make_sample_pattern(cache.seed, refined.spp);
  const int width = static_cast<int>(refined.entries());
  return for_each_entry_packet(cache, ctx, [&](SamplePacket& packet) {
    entry_directions(packet, cache, pattern);
    load_hits(packet, width, refined.plane);
    return shade_sample(packet, cache, ctx, refined.plane, no_consumer);
  });
}

bool visit_refined_samples(const SampleCache& cache, const RenderContext& ctx,
                           const std::function<long long(SamplePacket&)>& visit) {
  const RefinedSamples& refined = cache.refined;
  if (refined.spp == 0) return true;
  const SamplePattern pattern = make_sample_pattern(cache.seed, refined.spp);
  const int width = static_cast<int>(refined.entries());
  return for_each_entry_packet(cache, ctx, [&](SamplePacket& packet) {
    entry_directions(packet, cache, pattern);
    load_hits(packet, width, refined.plane);
    return visit(packet);
  });
}

}  // namespace gloss
