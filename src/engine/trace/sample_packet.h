#pragma once
// One row of 16 samples traced and shaded together: Embree's 16-ray packets
// (rtcIntersect16, rtcOccluded16) for the rays, and structure-of-arrays lanes for the maths in
// between, so each per-sample step runs as vector code (16 floats = one AVX-512 register).
// Steps in data-flow order: directions -> primary hits -> surfaces -> per light: shadow rays
// and light factors. Lane i is pixel (x0 + i, y0) of the cached region. A row (not a 4 x 4 block,
// which Embree traces slightly faster: docs/engine.md, "Packet shape") makes each field of a
// packet one 64-byte cache line of the cache's arrays, which store_lanes can then stream past
// the caches without first reading the line (the per-sample cache is written once and read back
// only by later edits).
#include <algorithm>
#include <cstdint>
#include <cstring>

#include "engine/parallel_loops.h"
#include "engine/render_context.h"
#include "engine/simd/lane_mask.h"
#include "engine/simd/lane_store.h"
#include "engine/simd/lanes.h"
#include "engine/trace/sample_cache.h"
#include "engine/trace/texture_lanes.h"
#include "shading/environment.h"
#include "shading/sampling.h"
#include "shading/surface.h"

namespace gloss {

struct SamplePacket {
  int x0, y0, x1, y1;             // region pixels covered, [x0, x1) x [y0, y1)
  alignas(64) int valid[kLanes];  // Embree mask: -1 inside the region (64-B aligned)
  alignas(64) double dir_x[kLanes], dir_y[kLanes], dir_z[kLanes];  // unit
  // Primary hits: object = geomID (-1: missed), prim = triangle (0 for spheres), t along the
  // unit direction, Embree's barycentrics u, v.
  alignas(64) std::int32_t object[kLanes];
  alignas(64) std::uint32_t prim[kLanes];
  alignas(64) float t[kLanes], u[kLanes], v[kLanes];

  SamplePacket(int bx0, int by0, int bx1, int by1);
};

// Surfaces of the lanes (surface.h Surface, split by component). hit is -1 where the primary
// ray hit something.
struct SurfaceLanes {
  alignas(64) int hit[kLanes];
  alignas(64) float px[kLanes], py[kLanes], pz[kLanes];  // point
  alignas(64) float nx[kLanes], ny[kLanes], nz[kLanes];  // shading normal
  alignas(64) float gx[kLanes], gy[kLanes], gz[kLanes];  // geometric normal
  alignas(64) float vx[kLanes], vy[kLanes], vz[kLanes];  // to the eye
  alignas(64) float lift[kLanes];                        // Surface::lift

  Surface get(int i) const {
    Surface s;
    s.p = {px[i], py[i], pz[i]};
    s.n = {nx[i], ny[i], nz[i]};
    s.ng = {gx[i], gy[i], gz[i]};
    s.v = {vx[i], vy[i], vz[i]};
    s.lift = lift[i];
    return s;
  }
  void set(int i, const Surface& s) {
    px[i] = s.p.x, py[i] = s.p.y, pz[i] = s.p.z;
    nx[i] = s.n.x, ny[i] = s.n.y, nz[i] = s.n.z;
    gx[i] = s.ng.x, gy[i] = s.ng.y, gz[i] = s.ng.z;
    vx[i] = s.v.x, vy[i] = s.v.y, vz[i] = s.v.z;
    lift[i] = s.lift;
  }
};

// shading.h's LightFactors of one light for the lanes; zeros where unlit or missed.
struct LightLanes {
  alignas(64) float diffuse_weight[kLanes], spec_weight[kLanes];
  alignas(64) float cos_phong[kLanes], cos_blinn[kLanes];
};

// Directions of sample `stratum` for every lane (y is a region row; the pattern and the camera
// use image rows).
void packet_directions(SamplePacket& packet, const SampleCache& cache, const SamplePattern& pattern,
                       int stratum);

// Directions through image points (px[i], py[i]) (pixels, image rows, not region rows); every
// lane must hold a point inside the image, masked-off lanes too.
void packet_directions_at(SamplePacket& packet, const SampleCache& cache, const double* px,
                          const double* py);

// Traces the primary rays and fills the hit lanes; returns the rays traced.
long long trace_primary(SamplePacket& packet, const SampleCache& cache, const RenderContext& ctx);

// Hit lanes to and from a cache plane (the region is cache.width pixels wide).
void store_hits(const SamplePacket& packet, int width, SamplePlane& plane);
void load_hits(SamplePacket& packet, int width, const SamplePlane& plane);

void packet_surfaces(const SamplePacket& packet, const SampleCache& cache, const RenderContext& ctx,
                     SurfaceLanes& out);

// Shadow rays (when planned) and light factors of planned light li; returns the rays traced.
long long packet_light(const SamplePacket& packet, const SurfaceLanes& surfaces,
                       const RenderContext& ctx, std::size_t li, LightLanes& out);

// The environment's fast-path factors of the lanes, one LightLanes per colour channel: the
// diffuse weight the irradiance / pi at n, the specular weight the lobe's mean around r, both at
// intensity 1, and cosines of 1 so that the factor pipeline's c^alpha leaves them as they are
// (engine/environment/environment_lanes.cpp). alpha_scale: per lane what a shininess map
// multiplies its material's alpha by (the plan's alpha channel; null without one): the lobe's
// level is the lane's own.
void environment_lanes(const SamplePacket& packet, const SurfaceLanes& surfaces,
                       const RenderContext& ctx, const float* alpha_scale, LightLanes (&out)[3]);

// The plan's alpha channel of texel lanes (null when the plan has none).
inline const float* alpha_lanes(const RenderContext& ctx, const TexelLanes& texels) {
  const int alpha = ctx.plan.textures.alpha_channel();
  return alpha >= 0 ? texels.channel[alpha] : nullptr;
}

// The map's radiance (intensity 1) towards each missed lane of packet, 0 where the lane hit
// (engine/environment/environment_stage.cpp): the sky.
void sky_lanes(const SamplePacket& packet, const Environment& environment,
               const EnvironmentRotation<float>& rotation, glm::vec3 (&out)[kLanes]);

void store_light(const SamplePacket& packet, int width, const LightLanes& lanes,
                 LightFactorPlane& plane);

// Copies lanes to a width-wide image array and back (clipped to the packet's pixels).
template <class T>
void store_lanes(const SamplePacket& packet, int width, const T* lanes, T* image) {
  T* row = image + static_cast<std::size_t>(packet.y0) * width + packet.x0;
  for (int i = 0; i < packet.x1 - packet.x0; ++i) row[i] = lanes[i];
}

// store_lanes for arrays written once and read much later (the per-sample cache): a whole,
// aligned line is streamed past the caches (simd/lane_store.h).
template <class T>
void stream_lanes(const SamplePacket& packet, int width, const T* lanes, T* image) {
  T* row = image + static_cast<std::size_t>(packet.y0) * width + packet.x0;
  if (packet.x1 - packet.x0 == kLanes && stream_lane_line(lanes, row)) return;
  store_lanes(packet, width, lanes, image);
}

template <class T>
void load_lanes(const SamplePacket& packet, int width, const T* image, T* lanes, T fill) {
  for (int i = 0; i < kLanes; ++i) lanes[i] = fill;
  const T* row = image + static_cast<std::size_t>(packet.y0) * width + packet.x0;
  for (int i = 0; i < packet.x1 - packet.x0; ++i) lanes[i] = row[i];
}

// Whether some lane's primary ray hit something.
inline bool any_hit(const SamplePacket& packet) {
  return !all_lanes_negative(packet.object);
}

// The samples per pixel a plane's samples share their pixel with (their footprint's share).
inline int plane_spp(const SampleCache& cache, const SamplePlane& plane) {
  return &plane == &cache.refined.plane ? cache.refined.spp : cache.target_spp;
}

// Surfaces of the packet's hits, then the maps there (stored in plane; handed to *texels when
// given), then per planned light the factors, stored in plane and each also handed to
// on_light(li, lanes) for a consumer fused into the same pass. Returns the shadow rays traced.
template <class OnLight>
long long shade_sample(const SamplePacket& packet, const SampleCache& cache,
                       const RenderContext& ctx, SamplePlane& plane, OnLight&& on_light,
                       TexelLanes* texels = nullptr) {
  TexelLanes own_texels;
  TexelLanes& maps = texels != nullptr ? *texels : own_texels;
  const std::size_t channels = ctx.plan.textures.channels();
  if (!any_hit(packet)) {  // all background (image borders): every light's factors are zero
    // The texels first, as on hits: on_light may read them (a shininess map's alpha lanes).
    if (channels > 0) {
      unit_texels(channels, maps);
      store_texels(packet, cache.width, maps, plane);
    }
    LightLanes none{};
    for (std::size_t li = 0; li < ctx.plan.slots(); ++li) {
      store_light(packet, cache.width, none, plane.lights[li]);
      on_light(li, none);
    }
    return 0;
  }
  SurfaceLanes surfaces;
  packet_surfaces(packet, cache, ctx, surfaces);
  if (ctx.plan.textures.any()) {  // before the lights: normal maps turn n
    texture_lanes(packet, cache, ctx, plane_spp(cache, plane), surfaces, maps);
    store_texels(packet, cache.width, maps, plane);
  }
  long long rays = 0;
  for (std::size_t li = 0; li < ctx.plan.lights.size(); ++li) {
    LightLanes lanes;
    rays += packet_light(packet, surfaces, ctx, li, lanes);
    store_light(packet, cache.width, lanes, plane.lights[li]);
    on_light(li, lanes);
  }
  if (ctx.plan.environment) {  // the fast path's three slots (environment_lanes.h)
    LightLanes channels[3];
    environment_lanes(packet, surfaces, ctx, alpha_lanes(ctx, maps), channels);
    for (int c = 0; c < 3; ++c) {
      const std::size_t slot = ctx.plan.environment_slot(c);
      store_light(packet, cache.width, channels[c], plane.lights[slot]);
      on_light(slot, channels[c]);
    }
  }
  return rays;
}

// Traces the packet's primary rays (its directions set) into plane, `width` entries a row: the
// hits stored, then shade_sample. Returns the rays traced.
template <class OnLight>
long long trace_directed_sample(SamplePacket& packet, const SampleCache& cache,
                                const RenderContext& ctx, int width, SamplePlane& plane,
                                OnLight&& on_light, TexelLanes* texels = nullptr) {
  const long long rays = trace_primary(packet, cache, ctx);
  store_hits(packet, width, plane);
  return rays + shade_sample(packet, cache, ctx, plane, on_light, texels);
}

// Traces sample `stratum` of the packet into plane: directions, then trace_directed_sample.
template <class OnLight>
long long trace_sample(SamplePacket& packet, const SampleCache& cache, const RenderContext& ctx,
                       const SamplePattern& pattern, int stratum, SamplePlane& plane,
                       OnLight&& on_light, TexelLanes* texels = nullptr) {
  packet_directions(packet, cache, pattern, stratum);
  return trace_directed_sample(packet, cache, ctx, cache.width, plane, on_light, texels);
}

// Runs f(packet) -> rays over the cached region's packets, band by band of whole rows on
// oneTBB workers (parallel_rows): the caches' arrays are then read and written as long
// streams. Adds the rays to ctx.rays. false when cancelled.
template <class F>
bool for_each_packet(const SampleCache& cache, const RenderContext& ctx, F&& f) {
  return parallel_rows(cache.width, cache.height, ctx.cancel, [&](int y0, int y1) {
    long long rays = 0;
    for (int y = y0; y < y1; ++y) {
      for (int x = 0; x < cache.width; x += kLanes) {
        SamplePacket packet(x, y, std::min(x + kLanes, cache.width), y + 1);
        rays += f(packet);
      }
    }
    finish_streaming_stores();
    if (ctx.rays != nullptr) ctx.rays->fetch_add(rays, std::memory_order_relaxed);
  });
}

}  // namespace gloss
