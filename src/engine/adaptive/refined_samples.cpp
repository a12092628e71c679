#include "engine/adaptive/refined_samples.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <utility>

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

// The entries of up to kPacketsPerChunk packets, [begin, end) each (at most kLanes).
struct EntryRange {
  std::size_t begin, end;
};

// The pixel positions of the samples of a chunk's packets: packet k's lane i at k * kLanes + i
// (a masked-off lane repeats its packet's last entry: a point inside the image nobody reads).
// Sample (entry mod spp) of pixel pixels[entry / spp]. The offsets' hash is a chain of ten
// dependent multiplies: made one packet at a time it waited on that chain (12 % of the refined
// trace on the benchmark scene); over a whole chunk the lanes' chains overlap.
struct ChunkPositions {
  alignas(64) double x[kPacketsPerChunk * kLanes], y[kPacketsPerChunk * kLanes];

  ChunkPositions(const SampleCache& cache, const SamplePattern& pattern, const EntryRange* packets,
                 int n) {
    const RefinedSamples& refined = cache.refined;
    alignas(64) int lane_x[kPacketsPerChunk * kLanes], lane_row[kPacketsPerChunk * kLanes],
        lane_stratum[kPacketsPerChunk * kLanes];
    for (int p = 0; p < n; ++p) {
      // Pixels and strata by increments (no division per lane; stride < count).
      const EntryRange& range = packets[p];
      std::size_t k = range.begin / static_cast<std::size_t>(refined.spp);
      int s = static_cast<int>(range.begin % static_cast<std::size_t>(refined.spp));
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
        const int lane = p * kLanes + i;
        lane_x[lane] = x;
        lane_row[lane] = row;
        lane_stratum[lane] = stratum;
        if (range.begin + static_cast<std::size_t>(i) + 1 >= range.end) continue;
        stratum += pattern.stride;  // sample_stratum of s + 1
        if (stratum >= pattern.count) stratum -= pattern.count;
        if (++s == refined.spp) {
          s = 0;
          stratum = 0;
          ++k;
        }
      }
    }
    const int lanes = n * kLanes;
    SampleOffset offset[kPacketsPerChunk * kLanes];
    sample_offsets(pattern, lane_stratum, lane_x, lane_row, lanes, offset);
    for (int i = 0; i < lanes; ++i) {
      x[i] = static_cast<double>(lane_x[i]) + static_cast<double>(offset[i].dx);
      y[i] = static_cast<double>(lane_row[i]) + static_cast<double>(offset[i].dy);
    }
  }

  // Packet k's directions.
  void directions(SamplePacket& packet, const SampleCache& cache, int k) const {
    packet_directions_at(packet, cache, x + k * kLanes, y + k * kLanes);
  }
};

// Runs f(packet) -> rays over the refined entries' packets, their directions set, on oneTBB
// workers; adds the rays to ctx.rays. false when cancelled.
template <class F>
bool for_each_entry_packet(const SampleCache& cache, const RenderContext& ctx, F&& f) {
  const std::size_t entries = cache.refined.entries();
  const std::size_t per_chunk = static_cast<std::size_t>(kPacketsPerChunk) * kLanes;
  const int chunks = static_cast<int>((entries + per_chunk - 1) / per_chunk);
  const SamplePattern pattern = make_sample_pattern(cache.seed, cache.refined.spp);
  return parallel_chunks(chunks, ctx.cancel, [&](int chunk) {
    long long rays = 0;
    const std::size_t end = std::min(entries, (static_cast<std::size_t>(chunk) + 1) * per_chunk);
    EntryRange packets[kPacketsPerChunk] = {};
    int n = 0;
    for (std::size_t e = static_cast<std::size_t>(chunk) * per_chunk; e < end; e += kLanes) {
      packets[n++] = {e, std::min(e + kLanes, end)};
    }
    const ChunkPositions positions(cache, pattern, packets, n);
    for (int k = 0; k < n; ++k) {
      SamplePacket packet = entry_packet(packets[k].begin, packets[k].end);
      positions.directions(packet, cache, k);
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
  const int width = static_cast<int>(refined.entries());
  const bool done = for_each_entry_packet(cache, ctx, [&](SamplePacket& packet) {
    return trace_directed_sample(packet, cache, ctx, width, refined.plane, no_consumer);
  });
  if (!done) {
    refined.spp = 0;
    refined.pixels.clear();
  }
  return done;
}

namespace {
// A run of entries [begin, end) of the new refined plane, whose samples are traced afresh
// (pixels newly refined) or kept (pixels refined before).
struct EntryRun {
  std::size_t begin, end;
  bool traced;
};

// Copies the samples of kept pixels from `from` into `to`: the hits, and the light factors when
// they are current. copies[i] = (entry in from, entry in to) of a kept pixel's first sample.
// false when cancelled.
bool copy_kept_samples(const SamplePlane& from, SamplePlane& to,
                       const std::vector<std::pair<std::size_t, std::size_t>>& copies,
                       std::size_t spp, bool with_lights, const std::atomic<bool>* cancel) {
  constexpr std::size_t kPixelsPerChunk = 256;
  const int chunks = static_cast<int>((copies.size() + kPixelsPerChunk - 1) / kPixelsPerChunk);
  return parallel_chunks(chunks, cancel, [&](int chunk) {
    const std::size_t k0 = static_cast<std::size_t>(chunk) * kPixelsPerChunk;
    const std::size_t k1 = std::min(copies.size(), k0 + kPixelsPerChunk);
    for (std::size_t k = k0; k < k1; ++k) {
      const std::size_t a = copies[k].first, b = copies[k].second;
      auto copy = [&](const auto& src, auto& dst) { std::copy(&src[a], &src[a] + spp, &dst[b]); };
      copy(from.object, to.object);
      copy(from.prim, to.prim);
      copy(from.t, to.t);
      copy(from.u, to.u);
      copy(from.v, to.v);
      if (!with_lights) continue;
      for (std::size_t li = 0; li < to.lights.size(); ++li) {
        copy(from.lights[li].diffuse_weight, to.lights[li].diffuse_weight);
        copy(from.lights[li].spec_weight, to.lights[li].spec_weight);
        if (to.lights[li].unit_cosines) continue;  // no arrays (sample_cache.h)
        if (from.lights[li].unit_cosines) {        // all 1, not kept
          std::fill(&to.lights[li].cos_phong[b], &to.lights[li].cos_phong[b] + spp, 1.0f);
          std::fill(&to.lights[li].cos_blinn[b], &to.lights[li].cos_blinn[b] + spp, 1.0f);
          continue;
        }
        copy(from.lights[li].cos_phong, to.lights[li].cos_phong);
        copy(from.lights[li].cos_blinn, to.lights[li].cos_blinn);
      }
      for (std::size_t c = 0; c < to.texels.size(); ++c) copy(from.texels[c], to.texels[c]);
    }
  });
}
}  // namespace

bool update_refined_samples(SampleCache& cache, const RenderContext& ctx,
                            std::vector<std::uint32_t> pixels, bool lights_stale,
                            SamplePlane& spare, RefinedUpdate* counts) {
  RefinedSamples& old = cache.refined;
  const auto spp = static_cast<std::size_t>(old.spp);
  // Which entries of the new placement are kept and which traced: both lists ascend.
  std::vector<std::pair<std::size_t, std::size_t>> copies;
  std::vector<EntryRun> runs;
  std::size_t j = 0;
  for (std::size_t k = 0; k < pixels.size(); ++k) {
    while (j < old.pixels.size() && old.pixels[j] < pixels[k]) ++j;
    const bool kept = j < old.pixels.size() && old.pixels[j] == pixels[k];
    if (kept) copies.emplace_back(j * spp, k * spp);
    if (!runs.empty() && runs.back().traced == !kept) {
      runs.back().end += spp;
    } else {
      runs.push_back({k * spp, (k + 1) * spp, !kept});
    }
  }
  RefinedUpdate update;
  update.kept = copies.size();
  update.traced = pixels.size() - copies.size();
  update.dropped = old.pixels.size() - copies.size();
  if (counts != nullptr) *counts = update;

  RefinedSamples next;
  next.spp = old.spp;
  next.pixels = std::move(pixels);
  next.plane = std::move(spare);
  size_plane(next.plane, next.entries(), ctx.plan.plane_shape());
  // The light factors (and the maps' texels, made in the same pass) of kept samples are copied
  // when current (the same plan), else made anew.
  const bool copy_lights = !lights_stale && old.plane.lights.size() == next.plane.lights.size() &&
                           old.plane.texels.size() == next.plane.texels.size();
  const bool copied =
      copy_kept_samples(old.plane, next.plane, copies, spp, copy_lights, ctx.cancel);
  // Packets over the runs: traced entries get primary rays, kept ones with stale light factors
  // shadow rays from their kept hits; a packet never spans two runs.
  std::vector<EntryRun> packets;
  for (const EntryRun& run : runs) {
    if (!run.traced && copy_lights) continue;
    for (std::size_t e = run.begin; e < run.end; e += kLanes) {
      packets.push_back({e, std::min(e + kLanes, run.end), run.traced});
    }
  }
  const SamplePattern pattern = make_sample_pattern(cache.seed, next.spp);
  const int width = static_cast<int>(next.entries());
  const int chunks = static_cast<int>((packets.size() + kPacketsPerChunk - 1) / kPacketsPerChunk);
  // The directions read the new placement: cache.refined is swapped for the duration (and back
  // on cancellation).
  std::swap(cache.refined, next);
  const bool done =
      copied && parallel_chunks(chunks, ctx.cancel, [&](int chunk) {
        long long rays = 0;
        const std::size_t p0 = static_cast<std::size_t>(chunk) * kPacketsPerChunk;
        const std::size_t p1 = std::min(packets.size(), p0 + kPacketsPerChunk);
        EntryRange ranges[kPacketsPerChunk] = {};
        for (std::size_t p = p0; p < p1; ++p) {
          ranges[p - p0] = {packets[p].begin, packets[p].end};
        }
        const ChunkPositions positions(cache, pattern, ranges, static_cast<int>(p1 - p0));
        for (std::size_t p = p0; p < p1; ++p) {
          SamplePacket packet = entry_packet(packets[p].begin, packets[p].end);
          positions.directions(packet, cache, static_cast<int>(p - p0));
          if (packets[p].traced) {
            rays += trace_primary(packet, cache, ctx);
            store_hits(packet, width, cache.refined.plane);
          } else {
            load_hits(packet, width, cache.refined.plane);
          }
          rays += shade_sample(packet, cache, ctx, cache.refined.plane, no_consumer);
        }
        finish_streaming_stores();
        if (ctx.rays != nullptr) ctx.rays->fetch_add(rays, std::memory_order_relaxed);
      });
  if (!done) std::swap(cache.refined, next);  // the old placement, as it was
  spare = std::move(next.plane);              // the memory of whichever plane is not in use
  return done;
}

bool recompute_refined_light_factors(SampleCache& cache, const RenderContext& ctx) {
  RefinedSamples& refined = cache.refined;
  if (refined.spp == 0) return true;
  size_plane(refined.plane, refined.entries(), ctx.plan.plane_shape());
  const int width = static_cast<int>(refined.entries());
  return for_each_entry_packet(cache, ctx, [&](SamplePacket& packet) {
    load_hits(packet, width, refined.plane);
    return shade_sample(packet, cache, ctx, refined.plane, no_consumer);
  });
}

bool visit_refined_samples(const SampleCache& cache, const RenderContext& ctx,
                           const std::function<long long(SamplePacket&)>& visit) {
  const RefinedSamples& refined = cache.refined;
  if (refined.spp == 0) return true;
  const int width = static_cast<int>(refined.entries());
  return for_each_entry_packet(cache, ctx, [&](SamplePacket& packet) {
    load_hits(packet, width, refined.plane);
    return visit(packet);
  });
}

}  // namespace gloss
