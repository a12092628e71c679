#include "sample_cache.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <embree3/rtcore.h>

#include "parallel_tiles.h"
#include "ray_packet.h"
#include "sampling.h"
#include "surface.h"

namespace gloss {

namespace {
constexpr int kLanes = 16;  // one Embree packet: a 4 x 4 block of pixels

// One 4 x 4 block of the cached region, clipped to it, and what its 16 lanes share.
struct Packet {
  int x0, y0, x1, y1;
  alignas(64) int valid[kLanes];  // Embree mask, -1 inside the region; Embree wants 64-B alignment
  std::size_t index[kLanes];      // pixel index in the region (0 for invalid lanes)
  glm::dvec3 exact_dir[kLanes];   // unit, in double: for rebuilding hit points
  glm::vec3 dir[kLanes];          // the same rounded to float: Embree's rays

  Packet(const SampleCache& cache, int bx, int by, int bx1, int by1)
      : x0(bx), y0(by), x1(bx1), y1(by1) {
    for (int i = 0; i < kLanes; ++i) {
      const int x = x0 + (i & 3), y = y0 + (i >> 2);
      valid[i] = x < x1 && y < y1 ? -1 : 0;
      index[i] = valid[i] ? static_cast<std::size_t>(y) * cache.width + x : 0;
    }
  }

  // Directions of sample `stratum` for every lane (y is a region row; the pattern and the
  // camera use image rows). Two loops: the offsets (integer hashing), then the vector maths.
  void compute_directions(const SampleCache& cache, const SamplePattern& pattern, int stratum) {
    double px[kLanes], py[kLanes];
    for (int i = 0; i < kLanes; ++i) {
      const int x = x0 + (i & 3), row = y0 + (i >> 2) + cache.row0;
      const SampleOffset o = sample_offset(pattern, stratum, x, row);
      px[i] = static_cast<double>(x) + static_cast<double>(o.dx);
      py[i] = static_cast<double>(row) + static_cast<double>(o.dy);
    }
    for (int i = 0; i < kLanes; ++i) {
      exact_dir[i] =
          camera_direction<double>(cache.camera_d, px[i], py[i], cache.width, cache.image_height);
      dir[i] = glm::vec3(exact_dir[i]);
    }
  }
};

long long trace_primary(const SampleCache& cache, const RenderContext& ctx, SamplePlane& plane,
                        const Packet& packet) {
  RTCRayHit16 rh;
  const glm::vec3 eye = cache.camera.eye;
  for (int i = 0; i < kLanes; ++i) {
    set_packet_ray(rh.ray, i, eye, packet.dir[i]);
    rh.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
  }
  RTCIntersectContext context = coherent_context();
  rtcIntersect16(packet.valid, ctx.embree->handle(), &context, &rh);
  long long rays = 0;
  for (int i = 0; i < kLanes; ++i) {
    if (!packet.valid[i]) continue;
    ++rays;
    const std::size_t idx = packet.index[i];
    if (rh.hit.geomID[i] == RTC_INVALID_GEOMETRY_ID) {
      plane.object[idx] = -1;
      plane.prim[idx] = 0;
      plane.t[idx] = plane.u[idx] = plane.v[idx] = 0.0f;
      continue;
    }
    const auto object = static_cast<std::int32_t>(rh.hit.geomID[i]);
    const Object& obj = ctx.scene->objects[static_cast<std::size_t>(object)];
    float t = rh.ray.tfar[i];
    if (obj.type == ObjectType::sphere) t = refine_sphere_hit(obj, eye, packet.exact_dir[i], t);
    plane.object[idx] = object;
    plane.prim[idx] = rh.hit.primID[i];
    plane.t[idx] = t;
    plane.u[idx] = rh.hit.u[i];
    plane.v[idx] = rh.hit.v[i];
  }
  return rays;
}

// Surfaces, shadow rays and light factors of one packet's samples in one plane.
long long shade_geometry(const SampleCache& cache, const RenderContext& ctx, SamplePlane& plane,
                         const Packet& packet) {
  HitGeometry geometry[kLanes];
  float t[kLanes];
  bool hit[kLanes];
  for (int i = 0; i < kLanes; ++i) {  // gather: scattered loads from the objects
    const std::int32_t object = packet.valid[i] ? plane.object[packet.index[i]] : -1;
    hit[i] = object >= 0;
    if (!hit[i]) {
      geometry[i] = HitGeometry{};
      geometry[i].sphere = true;  // any valid input: the lane's result is discarded
      t[i] = 1.0f;
      continue;
    }
    const std::size_t idx = packet.index[i];
    t[i] = plane.t[idx];
    geometry[i] = hit_geometry(ctx.scene->objects[static_cast<std::size_t>(object)],
                               plane.prim[idx], plane.u[idx], plane.v[idx]);
  }
  Surface surf[kLanes];
  for (int i = 0; i < kLanes; ++i) {
    surf[i] = surface_from(geometry[i], cache.camera.eye, packet.exact_dir[i], t[i]);
  }
  long long rays = 0;
  RTCIntersectContext context = coherent_context();
  for (std::size_t li = 0; li < ctx.plan.lights.size(); ++li) {
    const PointLight& light = ctx.scene->lights[static_cast<std::size_t>(ctx.plan.lights[li])];
    const bool unit_att = ctx.plan.unit_attenuation[li];
    alignas(64) int lit[kLanes];  // Embree mask, 64-byte aligned
    for (int i = 0; i < kLanes; ++i) {
      lit[i] = hit[i] && glm::dot(surf[i].n, light.position - surf[i].p) > 0.0f ? -1 : 0;
    }
    float vis[kLanes];
    std::fill(vis, vis + kLanes, 1.0f);
    if (ctx.plan.shadow_rays) {
      RTCRay16 ray;
      for (int i = 0; i < kLanes; ++i) {
        const glm::vec3 org = shadow_ray_origin(surf[i], t[i]);
        set_packet_ray(ray, i, org, light.position - org, kShadowRayEnd);
        rays += lit[i] ? 1 : 0;
      }
      rtcOccluded16(lit, ctx.embree->handle(), &context, &ray);
      for (int i = 0; i < kLanes; ++i) {
        if (lit[i] && ray.tfar[i] == -std::numeric_limits<float>::infinity()) vis[i] = 0.0f;
      }
    }
    // Two copies of the loop, so each sees a constant attenuation switch and vectorizes; the
    // (1, 0, 0) copy does no attenuation maths.
    LightFactors<float> factors[kLanes];
    if (unit_att) {
      for (int i = 0; i < kLanes; ++i) {
        factors[i] = light_factors<float>(surf[i].p, surf[i].n, surf[i].v, light.position,
                                          light.attenuation, true, vis[i]);
      }
    } else {
      for (int i = 0; i < kLanes; ++i) {
        factors[i] = light_factors<float>(surf[i].p, surf[i].n, surf[i].v, light.position,
                                          light.attenuation, false, vis[i]);
      }
    }
    auto& out = plane.lights[li];
    for (int i = 0; i < kLanes; ++i) {
      if (packet.valid[i]) out[packet.index[i]] = lit[i] ? factors[i] : LightFactors<float>{};
    }
  }
  return rays;
}

template <class F>
bool for_each_packet(const SampleCache& cache, const RenderContext& ctx, F&& f) {
  return parallel_tiles(cache.width, cache.height, ctx.cancel, [&](int x0, int y0, int x1, int y1) {
    long long rays = 0;
    for (int by = y0; by < y1; by += 4) {
      for (int bx = x0; bx < x1; bx += 4) {
        Packet packet(cache, bx, by, std::min(bx + 4, x1), std::min(by + 4, y1));
        rays += f(packet);
      }
    }
    if (ctx.rays != nullptr) ctx.rays->fetch_add(rays, std::memory_order_relaxed);
  });
}

// Sizes a plane for pixels and lights; buffers keep their capacity (no page faults on reuse).
void size_plane(SamplePlane& plane, std::size_t pixels, std::size_t lights) {
  plane.object.resize(pixels);
  plane.prim.resize(pixels);
  plane.t.resize(pixels);
  plane.u.resize(pixels);
  plane.v.resize(pixels);
  plane.lights.resize(lights);
  for (auto& l : plane.lights) l.resize(pixels);
}
}  // namespace

std::size_t SampleCache::bytes() const {
  std::size_t total = 0;
  for (const SamplePlane& p : planes) {
    total += p.object.size() * (sizeof(std::int32_t) + sizeof(std::uint32_t) + 3 * sizeof(float));
    for (const auto& l : p.lights) total += l.size() * sizeof(LightFactors<float>);
  }
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
  cache.width = width;
  cache.image_height = height;
  cache.row0 = row0;
  cache.height = rows < 0 ? height - row0 : rows;
  cache.target_spp = target_spp;
  cache.seed = scene.render.seed;
  cache.camera = make_camera_frame(scene.camera, width, height);
  cache.camera_d = make_camera_basis<double>(scene.camera, width, height);
}

bool add_samples(SampleCache& cache, const RenderContext& ctx, int count) {
  const int first = cache.samples();
  const std::size_t pixels = cache.pixel_count();
  for (int s = first; s < first + count; ++s) {
    if (!cache.spare.empty()) {
      cache.planes.push_back(std::move(cache.spare.back()));
      cache.spare.pop_back();
    } else {
      cache.planes.emplace_back();
    }
    size_plane(cache.planes.back(), pixels, ctx.plan.lights.size());
  }
  const SamplePattern pattern = make_sample_pattern(cache.seed, cache.target_spp);
  const bool done = for_each_packet(cache, ctx, [&](Packet& packet) {
    long long rays = 0;
    for (int s = first; s < first + count; ++s) {
      SamplePlane& plane = cache.planes[static_cast<std::size_t>(s)];
      packet.compute_directions(cache, pattern, sample_stratum(pattern, s));
      rays += trace_primary(cache, ctx, plane, packet);
      rays += shade_geometry(cache, ctx, plane, packet);
    }
    return rays;
  });
  if (!done) {
    while (cache.samples() > first) {
      cache.spare.push_back(std::move(cache.planes.back()));
      cache.planes.pop_back();
    }
  }
  return done;
}

bool recompute_light_factors(SampleCache& cache, const RenderContext& ctx) {
  for (SamplePlane& plane : cache.planes) {
    size_plane(plane, cache.pixel_count(), ctx.plan.lights.size());
  }
  const SamplePattern pattern = make_sample_pattern(cache.seed, cache.target_spp);
  return for_each_packet(cache, ctx, [&](Packet& packet) {
    long long rays = 0;
    for (int s = 0; s < cache.samples(); ++s) {
      packet.compute_directions(cache, pattern, sample_stratum(pattern, s));
      rays += shade_geometry(cache, ctx, cache.planes[static_cast<std::size_t>(s)], packet);
    }
    return rays;
  });
}

}  // namespace gloss
