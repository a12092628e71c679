#include "sample_cache.h"

#include <cmath>
#include <limits>

#include <embree3/rtcore.h>

#include "parallel_tiles.h"
#include "sampling.h"
#include "surface.h"

namespace gloss {

namespace {
constexpr int kPacketSide = 4;  // 4 x 4 = 16 rays per Embree packet

// The pixels of one 4 x 4 packet, clipped to the tile.
struct Block {
  int x0, y0, x1, y1;
  bool lane(int i, int& x, int& y) const {
    x = x0 + i % kPacketSide;
    y = y0 + i / kPacketSide;
    return x < x1 && y < y1;
  }
};

RTCIntersectContext coherent_context() {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  return context;
}

// y is a row of the cached region; the sample pattern and the camera use image rows.
glm::vec3 sample_direction(const SampleCache& cache, int x, int y, int s) {
  const int row = y + cache.row0;
  const SampleOffset o = sample_offset(cache.seed, x, row, s, cache.target_spp);
  return primary_direction(cache.camera, static_cast<float>(x) + o.dx,
                           static_cast<float>(row) + o.dy, cache.width, cache.image_height);
}

long long trace_primary(const SampleCache& cache, const RenderContext& ctx, SamplePlane& plane,
                        int s, const Block& block) {
  RTCRayHit16 rh;
  int valid[16];
  int lanes = 0;
  for (int i = 0; i < 16; ++i) {
    int x, y;
    valid[i] = block.lane(i, x, y) ? -1 : 0;
    const glm::vec3 dir = valid[i] ? sample_direction(cache, x, y, s) : glm::vec3(0, 0, 1);
    lanes += valid[i] ? 1 : 0;
    rh.ray.org_x[i] = cache.camera.eye.x;
    rh.ray.org_y[i] = cache.camera.eye.y;
    rh.ray.org_z[i] = cache.camera.eye.z;
    rh.ray.dir_x[i] = dir.x;
    rh.ray.dir_y[i] = dir.y;
    rh.ray.dir_z[i] = dir.z;
    rh.ray.tnear[i] = 0.0f;
    rh.ray.tfar[i] = std::numeric_limits<float>::infinity();
    rh.ray.time[i] = 0.0f;
    rh.ray.mask[i] = 0xffffffffu;
    rh.ray.id[i] = static_cast<unsigned>(i);
    rh.ray.flags[i] = 0;
    rh.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
  }
  RTCIntersectContext context = coherent_context();
  rtcIntersect16(valid, ctx.embree->handle(), &context, &rh);
  for (int i = 0; i < 16; ++i) {
    int x, y;
    if (!block.lane(i, x, y)) continue;
    const std::size_t idx = static_cast<std::size_t>(y) * cache.width + x;
    if (rh.hit.geomID[i] == RTC_INVALID_GEOMETRY_ID) {
      plane.object[idx] = -1;
      plane.prim[idx] = 0;
      plane.t[idx] = plane.u[idx] = plane.v[idx] = 0.0f;
      continue;
    }
    const auto object = static_cast<std::int32_t>(rh.hit.geomID[i]);
    float t = rh.ray.tfar[i];
    const Object& obj = ctx.scene->objects[static_cast<std::size_t>(object)];
    if (obj.type == ObjectType::sphere) {
      const glm::vec3 dir(rh.ray.dir_x[i], rh.ray.dir_y[i], rh.ray.dir_z[i]);
      t = refine_sphere_hit(obj, cache.camera.eye, dir, t);
    }
    plane.object[idx] = object;
    plane.prim[idx] = rh.hit.primID[i];
    plane.t[idx] = t;
    plane.u[idx] = rh.hit.u[i];
    plane.v[idx] = rh.hit.v[i];
  }
  return lanes;
}

long long shade_geometry(const SampleCache& cache, const RenderContext& ctx, SamplePlane& plane,
                         int s, const Block& block) {
  Surface surf[16];
  float t[16];
  bool hit[16];
  std::size_t index[16];
  for (int i = 0; i < 16; ++i) {
    int x, y;
    hit[i] = false;
    if (!block.lane(i, x, y)) continue;
    index[i] = static_cast<std::size_t>(y) * cache.width + x;
    const std::int32_t object = plane.object[index[i]];
    if (object < 0) continue;
    hit[i] = true;
    t[i] = plane.t[index[i]];
    surf[i] = surface_at(ctx.scene->objects[static_cast<std::size_t>(object)], plane.prim[index[i]],
                         plane.u[index[i]], plane.v[index[i]], cache.camera.eye,
                         sample_direction(cache, x, y, s), t[i]);
  }
  long long rays = 0;
  RTCIntersectContext context = coherent_context();
  for (std::size_t li = 0; li < ctx.plan.lights.size(); ++li) {
    const PointLight& light = ctx.scene->lights[static_cast<std::size_t>(ctx.plan.lights[li])];
    const bool unit_att = ctx.plan.unit_attenuation[li];
    float vis[16];
    int valid[16];
    for (int i = 0; i < 16; ++i) {
      vis[i] = 1.0f;
      valid[i] = hit[i] && glm::dot(surf[i].n, light.position - surf[i].p) > 0.0f ? -1 : 0;
    }
    if (ctx.plan.shadow_rays) {
      RTCRay16 ray;
      for (int i = 0; i < 16; ++i) {
        const glm::vec3 org = valid[i] ? shadow_ray_origin(surf[i], t[i]) : glm::vec3(0.0f);
        const glm::vec3 dir = valid[i] ? light.position - org : glm::vec3(0, 0, 1);
        ray.org_x[i] = org.x;
        ray.org_y[i] = org.y;
        ray.org_z[i] = org.z;
        ray.dir_x[i] = dir.x;
        ray.dir_y[i] = dir.y;
        ray.dir_z[i] = dir.z;
        ray.tnear[i] = 0.0f;
        // The segment ends just short of the light: a light resting on a surface still lights
        // the side it is on.
        ray.tfar[i] = 1.0f - 1e-5f;
        ray.time[i] = 0.0f;
        ray.mask[i] = 0xffffffffu;
        ray.id[i] = static_cast<unsigned>(i);
        ray.flags[i] = 0;
        rays += valid[i] ? 1 : 0;
      }
      rtcOccluded16(valid, ctx.embree->handle(), &context, &ray);
      for (int i = 0; i < 16; ++i) {
        if (valid[i] && ray.tfar[i] == -std::numeric_limits<float>::infinity()) vis[i] = 0.0f;
      }
    }
    std::vector<LightFactors<float>>& out = plane.lights[li];
    for (int i = 0; i < 16; ++i) {
      int x, y;
      if (!block.lane(i, x, y)) continue;
      out[index[i]] = valid[i]
                          ? light_factors<float>(surf[i].p, surf[i].n, surf[i].v, light.position,
                                                 light.attenuation, unit_att, vis[i])
                          : LightFactors<float>{};
    }
  }
  return rays;
}

void allocate_lights(SamplePlane& plane, std::size_t lights, std::size_t pixels) {
  plane.lights.resize(lights);
  for (auto& l : plane.lights) l.resize(pixels);
}

template <class F>
bool for_each_block(const SampleCache& cache, const RenderContext& ctx, F&& f) {
  return parallel_tiles(cache.width, cache.height, ctx.cancel, [&](int x0, int y0, int x1, int y1) {
    long long rays = 0;
    for (int by = y0; by < y1; by += kPacketSide) {
      for (int bx = x0; bx < x1; bx += kPacketSide) {
        rays += f(Block{bx, by, std::min(bx + kPacketSide, x1), std::min(by + kPacketSide, y1)});
      }
    }
    if (ctx.rays != nullptr) ctx.rays->fetch_add(rays, std::memory_order_relaxed);
  });
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
  cache.width = width;
  cache.image_height = height;
  cache.row0 = row0;
  cache.height = rows < 0 ? height - row0 : rows;
  cache.target_spp = target_spp;
  cache.seed = scene.render.seed;
  cache.camera = make_camera_frame(scene.camera, width, height);
  return cache;
}

bool add_samples(SampleCache& cache, const RenderContext& ctx, int count) {
  const int first = cache.samples();
  const std::size_t pixels = cache.pixel_count();
  cache.planes.resize(static_cast<std::size_t>(first + count));
  for (int s = first; s < first + count; ++s) {
    SamplePlane& plane = cache.planes[static_cast<std::size_t>(s)];
    plane.object.resize(pixels);
    plane.prim.resize(pixels);
    plane.t.resize(pixels);
    plane.u.resize(pixels);
    plane.v.resize(pixels);
    allocate_lights(plane, ctx.plan.lights.size(), pixels);
  }
  const bool done = for_each_block(cache, ctx, [&](const Block& block) {
    long long rays = 0;
    for (int s = first; s < first + count; ++s) {
      SamplePlane& plane = cache.planes[static_cast<std::size_t>(s)];
      rays += trace_primary(cache, ctx, plane, s, block);
      rays += shade_geometry(cache, ctx, plane, s, block);
    }
    return rays;
  });
  if (!done) cache.planes.resize(static_cast<std::size_t>(first));
  return done;
}

bool recompute_light_factors(SampleCache& cache, const RenderContext& ctx) {
  for (SamplePlane& plane : cache.planes) {
    allocate_lights(plane, ctx.plan.lights.size(), cache.pixel_count());
  }
  return for_each_block(cache, ctx, [&](const Block& block) {
    long long rays = 0;
    for (int s = 0; s < cache.samples(); ++s) {
      rays += shade_geometry(cache, ctx, cache.planes[static_cast<std::size_t>(s)], s, block);
    }
    return rays;
  });
}

}  // namespace gloss
