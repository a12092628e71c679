#include "sample_packet.h"

#include <cmath>
#include <limits>
#include <type_traits>

#include <embree3/rtcore.h>
#include <immintrin.h>

#include "camera.h"
#include "lane_gather.h"
#include "lane_mask.h"
#include "ray_packet.h"
#include "shading.h"
#include "surface.h"

// The loops over kPacketLanes below are written so GCC vectorizes them (checked with
// -fopt-info-vec): structure-of-arrays loads and stores, inline maths, selects instead of
// branches. Surface data comes by 16-lane gathers from the surface table; only the refinement
// of sphere hits stays scalar.

namespace gloss {

SamplePacket::SamplePacket(int bx0, int by0, int bx1, int by1)
    : x0(bx0), y0(by0), x1(bx1), y1(by1) {
  for (int i = 0; i < kPacketLanes; ++i) valid[i] = x0 + i < x1 && y0 < y1 ? -1 : 0;
}

namespace {
// Scales the 16 vectors (x[i], y[i], z[i]) to unit length. With AVX-512: the 14-bit reciprocal
// square root estimate and two Newton steps (14 -> 28 -> 56 bits; lengths within a few double
// ulp of 1), about a third of the cost of a double square root and division per lane here.
// Directions then differ from camera_direction<double> (the reference path, and the scalar
// build's fallback below) by a few double ulp: far inside the accuracy contract.
void normalize_lanes(double* x, double* y, double* z) {
#if defined(__AVX512F__)
  const __m512d three_halves = _mm512_set1_pd(1.5), half = _mm512_set1_pd(0.5);
  for (int k = 0; k < kPacketLanes; k += 8) {
    const __m512d vx = _mm512_load_pd(x + k), vy = _mm512_load_pd(y + k),
                  vz = _mm512_load_pd(z + k);
    const __m512d n2 = _mm512_fmadd_pd(vx, vx, _mm512_fmadd_pd(vy, vy, _mm512_mul_pd(vz, vz)));
    const __m512d half_n2 = _mm512_mul_pd(half, n2);
    __m512d r = _mm512_maskz_rsqrt14_pd(0xff, n2);  // masked: see lane_gather.h
    for (int step = 0; step < 2; ++step) {          // r (3/2 - n2 r^2 / 2)
      r = _mm512_mul_pd(r, _mm512_fnmadd_pd(half_n2, _mm512_mul_pd(r, r), three_halves));
    }
    _mm512_store_pd(x + k, _mm512_mul_pd(vx, r));
    _mm512_store_pd(y + k, _mm512_mul_pd(vy, r));
    _mm512_store_pd(z + k, _mm512_mul_pd(vz, r));
  }
#else
  for (int i = 0; i < kPacketLanes; ++i) {
    const double r = 1.0 / std::sqrt(x[i] * x[i] + y[i] * y[i] + z[i] * z[i]);
    x[i] *= r;
    y[i] *= r;
    z[i] *= r;
  }
#endif
}
}  // namespace

void packet_directions(SamplePacket& packet, const SampleCache& cache, const SamplePattern& pattern,
                       int stratum) {
  alignas(64) double px[kPacketLanes], py[kPacketLanes];
  if (pattern.count <= 1) {  // pixel centres; sample_offset would say so lane by lane
    for (int i = 0; i < kPacketLanes; ++i) {
      px[i] = static_cast<double>(packet.x0 + i) + 0.5;
      py[i] = static_cast<double>(packet.y0 + cache.row0) + 0.5;
    }
  } else {
    for (int i = 0; i < kPacketLanes; ++i) {  // integer hashing
      const int x = packet.x0 + i, row = packet.y0 + cache.row0;
      const SampleOffset o = sample_offset(pattern, stratum, x, row);
      px[i] = static_cast<double>(x) + static_cast<double>(o.dx);
      py[i] = static_cast<double>(row) + static_cast<double>(o.dy);
    }
  }
  // camera_direction<double> with its normalisation done by normalize_lanes.
  const CameraBasis<double>& basis = cache.camera_d;
  const double to_x = 2.0 / cache.width, to_y = 2.0 / cache.image_height;
  for (int i = 0; i < kPacketLanes; ++i) {
    const double sx = (px[i] * to_x - 1.0) * basis.scale_x;
    const double sy = (1.0 - py[i] * to_y) * basis.scale_y;
    const glm::dvec3 d = basis.forward + sx * basis.right + sy * basis.up;
    packet.dir_x[i] = d.x;
    packet.dir_y[i] = d.y;
    packet.dir_z[i] = d.z;
  }
  normalize_lanes(packet.dir_x, packet.dir_y, packet.dir_z);
}

long long trace_primary(SamplePacket& packet, const SampleCache& cache, const RenderContext& ctx) {
  RTCRayHit16 rh;
  const glm::vec3 eye = cache.camera.eye;
  for (int i = 0; i < kPacketLanes; ++i) {
    const glm::vec3 dir(static_cast<float>(packet.dir_x[i]), static_cast<float>(packet.dir_y[i]),
                        static_cast<float>(packet.dir_z[i]));
    set_packet_ray(rh.ray, i, eye, dir);
    rh.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
  }
  RTCIntersectContext context = coherent_context();
  rtcIntersect16(packet.valid, ctx.embree->handle(), &context, &rh);
  const long long rays = count_set_lanes(packet.valid);
  for (int i = 0; i < kPacketLanes; ++i) {
    const bool hit = packet.valid[i] != 0 && rh.hit.geomID[i] != RTC_INVALID_GEOMETRY_ID;
    packet.object[i] = hit ? static_cast<std::int32_t>(rh.hit.geomID[i]) : -1;
    packet.prim[i] = hit ? rh.hit.primID[i] : 0u;
    packet.t[i] = hit ? rh.ray.tfar[i] : 0.0f;
    packet.u[i] = hit ? rh.hit.u[i] : 0.0f;
    packet.v[i] = hit ? rh.hit.v[i] : 0.0f;
  }
  if (ctx.plan.spheres) {
    for (int i = 0; i < kPacketLanes; ++i) {
      if (packet.object[i] < 0) continue;
      const Object& obj = ctx.scene->objects[static_cast<std::size_t>(packet.object[i])];
      if (obj.type != ObjectType::sphere) continue;
      const glm::dvec3 dir(packet.dir_x[i], packet.dir_y[i], packet.dir_z[i]);
      packet.t[i] = refine_sphere_hit(obj, eye, dir, packet.t[i]);
    }
  }
  return rays;
}

void store_hits(const SamplePacket& packet, int width, SamplePlane& plane) {
  stream_lanes(packet, width, packet.object, plane.object.data());
  stream_lanes(packet, width, packet.prim, plane.prim.data());
  stream_lanes(packet, width, packet.t, plane.t.data());
  stream_lanes(packet, width, packet.u, plane.u.data());
  stream_lanes(packet, width, packet.v, plane.v.data());
}

void load_hits(SamplePacket& packet, int width, const SamplePlane& plane) {
  load_lanes(packet, width, plane.object.data(), packet.object, -1);
  load_lanes(packet, width, plane.prim.data(), packet.prim, 0u);
  load_lanes(packet, width, plane.t.data(), packet.t, 0.0f);
  load_lanes(packet, width, plane.u.data(), packet.u, 0.0f);
  load_lanes(packet, width, plane.v.data(), packet.v, 0.0f);
}

namespace {
// HitGeometry of the lanes, split by component.
struct GeometryLanes {
  alignas(64) float a[3][kPacketLanes];  // centre or face normal
  alignas(64) float n[9][kPacketLanes];  // n0.xyz, n1.xyz, n2.xyz (smooth triangles)
  alignas(64) std::int32_t kind[kPacketLanes];
};

// The lanes' records of the scene's surface table.
LaneKinds gather_geometry(const SamplePacket& packet, const SurfaceTable& table,
                          GeometryLanes& out) {
  alignas(64) std::int32_t record[kPacketLanes];
#if defined(__AVX512F__)
  // In registers: lanes stored one by one and read back as a vector stall on store forwarding.
  const __m512i object = _mm512_load_si512(packet.object);
  const __m512i prim = _mm512_load_si512(packet.prim);
  const std::int32_t first = packet.object[0];
  const __mmask16 hit = _mm512_cmpge_epi32_mask(object, _mm512_setzero_si512());
  __m512i base, stride, kind;
  if (first >= 0 && _mm512_cmpeq_epi32_mask(object, _mm512_set1_epi32(first)) == 0xffff) {
    // One object (most packets): its base, stride and kind.
    const std::size_t k = static_cast<std::size_t>(first);
    base = _mm512_set1_epi32(static_cast<std::int32_t>(table.base[k]));
    stride = _mm512_set1_epi32(static_cast<std::int32_t>(table.stride[k]));
    kind = _mm512_set1_epi32(table.kind[k]);
  } else {
    alignas(64) std::int32_t index[kPacketLanes], kinds[kPacketLanes];
    alignas(64) std::uint32_t bases[kPacketLanes], strides[kPacketLanes];
    _mm512_store_si512(index, _mm512_maskz_mov_epi32(hit, object));  // missed lanes: 0
    const LaneGather by_object(index);
    by_object(table.base.data(), table.base.size(), bases);
    by_object(table.stride.data(), table.stride.size(), strides);
    by_object(table.kind.data(), table.kind.size(), kinds);
    base = _mm512_maskz_mov_epi32(hit, _mm512_load_si512(bases));
    stride = _mm512_load_si512(strides);
    // Missed lanes: record 0, a sphere.
    kind = _mm512_mask_mov_epi32(_mm512_set1_epi32(kSphere), hit, _mm512_load_si512(kinds));
  }
  _mm512_store_si512(record, _mm512_maskz_add_epi32(hit, base, _mm512_mullo_epi32(prim, stride)));
  _mm512_store_si512(out.kind, kind);
  // Missed lanes hold a sphere record (0) but never need sphere maths.
  const LaneKinds kinds = {_mm512_mask_cmpeq_epi32_mask(hit, kind, _mm512_set1_epi32(kSphere)) != 0,
                           _mm512_cmpeq_epi32_mask(kind, _mm512_set1_epi32(kSmoothTriangle)) != 0};
#else
  for (int i = 0; i < kPacketLanes; ++i) {
    record[i] = static_cast<std::int32_t>(table.record(packet.object[i], packet.prim[i]));
    out.kind[i] = packet.object[i] < 0 ? kSphere  // record 0
                                       : table.kind[static_cast<std::size_t>(packet.object[i])];
  }
  LaneKinds kinds = {false, false};
  for (int i = 0; i < kPacketLanes; ++i) {
    kinds.spheres |= out.kind[i] == kSphere && packet.object[i] >= 0;
    kinds.smooth |= out.kind[i] == kSmoothTriangle;
  }
#endif
  const LaneGather by_record(record);
  const std::size_t records = table.a[0].size();
  for (int c = 0; c < 3; ++c)
    by_record(table.a[static_cast<std::size_t>(c)].data(), records, out.a[c]);
  if (kinds.smooth) {  // else no lane reads the vertex normals (left unset)
    for (int c = 0; c < 9; ++c) {
      by_record(table.normals[static_cast<std::size_t>(c)].data(), records, out.n[c]);
    }
  }
  return kinds;
}

glm::vec3 lane_vec(const float (&a)[9][kPacketLanes], int k, int i) {
  return {a[3 * k][i], a[3 * k + 1][i], a[3 * k + 2][i]};
}

}  // namespace

namespace {
template <bool Spheres, bool Smooth>
void surfaces_of_kinds(const SamplePacket& packet, const GeometryLanes& geometry,
                       const glm::vec3& eye, SurfaceLanes& out) {
  for (int i = 0; i < kPacketLanes; ++i) {
    HitGeometry g;
    g.a = {geometry.a[0][i], geometry.a[1][i], geometry.a[2][i]};
    if constexpr (Smooth) {  // set only when some lane is smooth (gather_geometry)
      g.n0 = lane_vec(geometry.n, 0, i);
      g.n1 = lane_vec(geometry.n, 1, i);
      g.n2 = lane_vec(geometry.n, 2, i);
    }
    g.u = packet.u[i];
    g.v = packet.v[i];
    g.sphere = geometry.kind[i] == kSphere;
    g.smooth = geometry.kind[i] == kSmoothTriangle;
    const bool hit = packet.object[i] >= 0;
    const glm::dvec3 dir(packet.dir_x[i], packet.dir_y[i], packet.dir_z[i]);
    out.hit[i] = hit ? -1 : 0;
    out.set(i, surface_from<Spheres, Smooth>(g, eye, dir, hit ? packet.t[i] : 1.0f));
  }
}
}  // namespace

void packet_surfaces(const SamplePacket& packet, const SampleCache& cache, const RenderContext& ctx,
                     SurfaceLanes& out) {
  GeometryLanes geometry;
  const LaneKinds kinds = gather_geometry(packet, ctx.embree->surfaces(), geometry);
  const glm::vec3 eye = cache.camera.eye;
  if (kinds.spheres && kinds.smooth) {
    surfaces_of_kinds<true, true>(packet, geometry, eye, out);
  } else if (kinds.spheres) {
    surfaces_of_kinds<true, false>(packet, geometry, eye, out);
  } else if (kinds.smooth) {
    surfaces_of_kinds<false, true>(packet, geometry, eye, out);
  } else {
    surfaces_of_kinds<false, false>(packet, geometry, eye, out);
  }
}

long long packet_light(const SamplePacket& packet, const SurfaceLanes& surfaces,
                       const RenderContext& ctx, std::size_t li, LightLanes& out) {
  const PointLight& light = ctx.scene->lights[static_cast<std::size_t>(ctx.plan.lights[li])];
  alignas(64) int lit[kPacketLanes];  // Embree mask, 64-byte aligned
  for (int i = 0; i < kPacketLanes; ++i) {
    const Surface s = surfaces.get(i);
    lit[i] = surfaces.hit[i] != 0 && glm::dot(s.n, light.position - s.p) > 0.0f ? -1 : 0;
  }
  alignas(64) float vis[kPacketLanes];
  for (int i = 0; i < kPacketLanes; ++i) vis[i] = 1.0f;
  long long rays = 0;
  if (ctx.plan.shadow_rays) {
    RTCRay16 ray;
    for (int i = 0; i < kPacketLanes; ++i) {
      const glm::vec3 org = shadow_ray_origin(surfaces.get(i), packet.t[i]);
      set_packet_ray(ray, i, org, light.position - org, kShadowRayEnd);
    }
    rays = count_set_lanes(lit);
    RTCIntersectContext context = coherent_context();
    rtcOccluded16(lit, ctx.embree->handle(), &context, &ray);
    for (int i = 0; i < kPacketLanes; ++i) {
      vis[i] = lit[i] != 0 && ray.tfar[i] == -std::numeric_limits<float>::infinity() ? 0.0f : 1.0f;
    }
  }
  // One copy of the loop per attenuation switch, so each sees a constant and the (1, 0, 0) copy
  // does no attenuation maths.
  auto factors = [&](auto unit_attenuation) {
    for (int i = 0; i < kPacketLanes; ++i) {
      const Surface s = surfaces.get(i);
      const LightFactors<float> f =
          light_factors<float>(s.p, s.n, s.v, light.position, light.attenuation,
                               decltype(unit_attenuation)::value, vis[i]);
      const bool on = lit[i] != 0;
      out.diffuse_weight[i] = on ? f.diffuse_weight : 0.0f;
      out.spec_weight[i] = on ? f.spec_weight : 0.0f;
      out.cos_phong[i] = on ? f.cos_phong : 0.0f;
      out.cos_blinn[i] = on ? f.cos_blinn : 0.0f;
    }
  };
  if (ctx.plan.unit_attenuation[li]) {
    factors(std::true_type{});
  } else {
    factors(std::false_type{});
  }
  return rays;
}

void store_light(const SamplePacket& packet, int width, const LightLanes& lanes,
                 LightFactorPlane& plane) {
  stream_lanes(packet, width, lanes.diffuse_weight, plane.diffuse_weight.data());
  stream_lanes(packet, width, lanes.spec_weight, plane.spec_weight.data());
  stream_lanes(packet, width, lanes.cos_phong, plane.cos_phong.data());
  stream_lanes(packet, width, lanes.cos_blinn, plane.cos_blinn.data());
}

}  // namespace gloss
