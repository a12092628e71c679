#include "engine/trace/sample_cache.h"

#include "engine/adaptive/refined_samples.h"
#include "engine/best_fit.h"
#include "engine/trace/sample_packet.h"
#include "shading/sampling.h"

namespace gloss {

void size_plane(SamplePlane& plane, std::size_t pixels, PlaneShape shape) {
  plane.object.resize(pixels);
  plane.prim.resize(pixels);
  plane.t.resize(pixels);
  plane.u.resize(pixels);
  plane.v.resize(pixels);
  plane.lights.resize(shape.slots);
  for (std::size_t k = 0; k < shape.slots; ++k) {
    plane.lights[k].resize(pixels, k + shape.unit_cosine_slots >= shape.slots);
  }
  plane.texels.resize(shape.texels);
  for (UninitializedBuffer<float>& t : plane.texels) t.resize(pixels);
}

namespace {
std::size_t plane_bytes(const SamplePlane& p) {
  std::size_t cosines = 0;  // empty in the unit_cosines slots
  for (const LightFactorPlane& l : p.lights) cosines += l.cos_phong.size() + l.cos_blinn.size();
  return p.object.size() * (sizeof(std::int32_t) + sizeof(std::uint32_t) + 3 * sizeof(float)) +
         p.object.size() * p.lights.size() * 2 * sizeof(float) + cosines * sizeof(float) +
         p.object.size() * p.texels.size() * sizeof(float);
}
}  // namespace

std::size_t SampleCache::bytes() const {
  std::size_t total = plane_bytes(refined.plane) + refined.pixels.size() * sizeof(std::uint32_t);
  for (const SamplePlane& p : planes) total += plane_bytes(p);
  return total;
}

SampleCache make_sample_cache(const Scene& scene, int width, int height, int target_spp, int row0,
                              int rows) {
  SampleCache cache;
  reset_sample_cache(cache, scene, width, height, target_spp, row0, rows);
  return cache;
}

void reset_sample_cache(SampleCache& cache, const Scene& scene, int width, int height,
                        int target_spp, int row0, int rows) {
  for (SamplePlane& plane : cache.planes) cache.spare.push_back(std::move(plane));
  cache.planes.clear();
  cache.refined.spp = 0;
  cache.refined.pixels.clear();
  cache.width = width;
  cache.image_height = height;
  cache.row0 = row0;
  cache.height = rows < 0 ? height - row0 : rows;
  cache.target_spp = target_spp;
  cache.seed = scene.render.seed;
  cache.camera = make_camera_frame(scene.camera, width, height);
  cache.camera_d = make_camera_basis<double>(scene.camera, width, height);
}

void append_planes(SampleCache& cache, PlaneShape shape, int count) {
  const std::size_t pixels = cache.pixel_count();
  for (int s = 0; s < count; ++s) {
    if (!cache.spare.empty()) {
      const auto best = best_fit(cache.spare.begin(), cache.spare.end(), pixels,
                                 [](const SamplePlane& p) { return p.object.capacity(); });
      cache.planes.push_back(std::move(*best));
      cache.spare.erase(best);
    } else {
      cache.planes.emplace_back();
    }
    size_plane(cache.planes.back(), cache.pixel_count(), shape);
  }
}

void drop_planes(SampleCache& cache, int first) {
  while (cache.samples() > first) {
    cache.spare.push_back(std::move(cache.planes.back()));
    cache.planes.pop_back();
  }
}

bool add_samples(SampleCache& cache, const RenderContext& ctx, int count) {
  const int first = cache.samples();
  append_planes(cache, ctx.plan.plane_shape(), count);
  const SamplePattern pattern = make_sample_pattern(cache.seed, cache.target_spp);
  const bool done = for_each_packet(cache, ctx, [&](SamplePacket& packet) {
    long long rays = 0;
    for (int s = first; s < first + count; ++s) {
      rays += trace_sample(packet, cache, ctx, pattern, sample_stratum(pattern, s),
                           cache.planes[static_cast<std::size_t>(s)],
                           [](std::size_t, const LightLanes&) {});
    }
    return rays;
  });
  if (!done) drop_planes(cache, first);
  return done;
}

void reclaim_planes(SampleCache& into, SampleCache&& from) {
  for (SamplePlane& plane : from.planes) into.spare.push_back(std::move(plane));
  for (SamplePlane& plane : from.spare) into.spare.push_back(std::move(plane));
  from.planes.clear();
  from.spare.clear();
  if (into.refined.spp == 0 &&
      from.refined.plane.object.capacity() > into.refined.plane.object.capacity()) {
    into.refined.plane = std::move(from.refined.plane);
  }
}

void size_planes(SampleCache& cache, PlaneShape shape) {
  for (SamplePlane& plane : cache.planes) size_plane(plane, cache.pixel_count(), shape);
}

bool recompute_light_factors(SampleCache& cache, const RenderContext& ctx) {
  size_planes(cache, ctx.plan.plane_shape());
  const SamplePattern pattern = make_sample_pattern(cache.seed, cache.target_spp);
  const bool planes_done = for_each_packet(cache, ctx, [&](SamplePacket& packet) {
    long long rays = 0;
    for (int s = 0; s < cache.samples(); ++s) {
      SamplePlane& plane = cache.planes[static_cast<std::size_t>(s)];
      packet_directions(packet, cache, pattern, sample_stratum(pattern, s));
      load_hits(packet, cache.width, plane);
      rays += shade_sample(packet, cache, ctx, plane, [](std::size_t, const LightLanes&) {});
    }
    return rays;
  });
  return planes_done && recompute_refined_light_factors(cache, ctx);
}

bool visit_cached_samples(SampleCache& cache, const RenderContext& ctx,
                          const std::function<long long(SamplePacket&, SamplePlane&)>& visit) {
  const SamplePattern pattern = make_sample_pattern(cache.seed, cache.target_spp);
  return for_each_packet(cache, ctx, [&](SamplePacket& packet) {
    long long rays = 0;
    for (int s = 0; s < cache.samples(); ++s) {
      SamplePlane& plane = cache.planes[static_cast<std::size_t>(s)];
      packet_directions(packet, cache, pattern, sample_stratum(pattern, s));
      load_hits(packet, cache.width, plane);
      rays += visit(packet, plane);
    }
    return rays;
  });
}

}  // namespace gloss
