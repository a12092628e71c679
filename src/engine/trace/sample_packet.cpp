#include "engine/trace/sample_packet.h"

#include <cmath>
#include <limits>
#include <type_traits>

#include <embree3/rtcore.h>

#include "engine/simd/lane_gather.h"
#include "engine/simd/lane_mask.h"
#include "engine/simd/lane_math.h"
#include "engine/simd/lane_records.h"
#include "engine/trace/ray_packet.h"
#include "engine/trace/self_shadow.h"
#include "scene/camera.h"
#include "shading/light_source.h"
#include "shading/shading.h"
#include "shading/surface.h"

// The loops over kLanes below are written so GCC vectorizes them (checked with
// -fopt-info-vec): structure-of-arrays loads and stores, inline maths, selects instead of
// branches. Surface data comes by 16-lane gathers from the surface table; only the refinement
// of sphere hits stays scalar.

namespace gloss {

SamplePacket::SamplePacket(int bx0, int by0, int bx1, int by1)
    : x0(bx0), y0(by0), x1(bx1), y1(by1) {
  for (int i = 0; i < kLanes; ++i) valid[i] = x0 + i < x1 && y0 < y1 ? -1 : 0;
}

void packet_directions(SamplePacket& packet, const SampleCache& cache, const SamplePattern& pattern,
                       int stratum) {
  alignas(64) double px[kLanes], py[kLanes];
  if (pattern.count <= 1) {  // pixel centres; sample_offset would say so lane by lane
    for (int i = 0; i < kLanes; ++i) {
      px[i] = static_cast<double>(packet.x0 + i) + 0.5;
      py[i] = static_cast<double>(packet.y0 + cache.row0) + 0.5;
    }
  } else {
    alignas(64) int lane_x[kLanes], lane_row[kLanes], lane_stratum[kLanes];
    for (int i = 0; i < kLanes; ++i) {
      lane_x[i] = packet.x0 + i;
      lane_row[i] = packet.y0 + cache.row0;
      lane_stratum[i] = stratum;
    }
    SampleOffset offset[kLanes];
    sample_offsets(pattern, lane_stratum, lane_x, lane_row, kLanes, offset);  // integer hashing
    for (int i = 0; i < kLanes; ++i) {
      px[i] = static_cast<double>(lane_x[i]) + static_cast<double>(offset[i].dx);
      py[i] = static_cast<double>(lane_row[i]) + static_cast<double>(offset[i].dy);
    }
  }
  packet_directions_at(packet, cache, px, py);
}

void packet_directions_at(SamplePacket& packet, const SampleCache& cache, const double* px,
                          const double* py) {
  // camera_direction<double> with its normalisation done by normalize_lanes.
  const CameraBasis<double>& basis = cache.camera_d;
  const double to_x = 2.0 / cache.width, to_y = 2.0 / cache.image_height;
  for (int i = 0; i < kLanes; ++i) {
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
  for (int i = 0; i < kLanes; ++i) {
    const glm::vec3 dir(static_cast<float>(packet.dir_x[i]), static_cast<float>(packet.dir_y[i]),
                        static_cast<float>(packet.dir_z[i]));
    set_packet_ray(rh.ray, i, eye, dir);
    rh.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
  }
  RTCIntersectContext context = coherent_context();
  rtcIntersect16(packet.valid, ctx.embree->handle(), &context, &rh);
  const long long rays = count_set_lanes(packet.valid);
  for (int i = 0; i < kLanes; ++i) {
    const bool hit = packet.valid[i] != 0 && rh.hit.geomID[i] != RTC_INVALID_GEOMETRY_ID;
    packet.object[i] = hit ? static_cast<std::int32_t>(rh.hit.geomID[i]) : -1;
    packet.prim[i] = hit ? rh.hit.primID[i] : 0u;
    packet.t[i] = hit ? rh.ray.tfar[i] : 0.0f;
    packet.u[i] = hit ? rh.hit.u[i] : 0.0f;
    packet.v[i] = hit ? rh.hit.v[i] : 0.0f;
  }
  if (ctx.plan.spheres) {
    for (int i = 0; i < kLanes; ++i) {
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
  alignas(64) float a[3][kLanes];       // centre or face normal
  alignas(64) float n[9][kLanes];       // n0.xyz, n1.xyz, n2.xyz (smooth triangles)
  alignas(64) float planes[3][kLanes];  // the corners' tangent planes (smooth triangles)
  alignas(64) std::int32_t kind[kLanes];
};

// The lanes' records of the scene's surface table.
LaneKinds gather_geometry(const SamplePacket& packet, const SurfaceTable& table,
                          GeometryLanes& out) {
  alignas(64) std::int32_t record[kLanes];
  // Missed lanes hold a sphere record (0) but never need sphere maths.
  const ObjectColumns columns = {table.base.data(), table.stride.data(), table.kind.data(),
                                 table.base.size()};
  const KindsPresent present = lane_records(packet.object, packet.prim, columns, kSphere, kSphere,
                                            kSmoothTriangle, record, out.kind);
  const LaneKinds kinds = {present.probe, present.any};
  const LaneGather by_record(record);
  const std::size_t records = table.a[0].size();
  for (int c = 0; c < 3; ++c)
    by_record(table.a[static_cast<std::size_t>(c)].data(), records, out.a[c]);
  if (kinds.smooth) {  // else no lane reads the vertex normals (left unset)
    for (int c = 0; c < 9; ++c) {
      by_record(table.normals[static_cast<std::size_t>(c)].data(), records, out.n[c]);
    }
    for (int c = 0; c < 3; ++c) {
      by_record(table.planes[static_cast<std::size_t>(c)].data(), records, out.planes[c]);
    }
  }
  return kinds;
}

glm::vec3 lane_vec(const float (&a)[9][kLanes], int k, int i) {
  return {a[3 * k][i], a[3 * k + 1][i], a[3 * k + 2][i]};
}

}  // namespace

namespace {
template <bool Spheres, bool Smooth>
void surfaces_of_kinds(const SamplePacket& packet, const GeometryLanes& geometry,
                       const glm::vec3& eye, SurfaceLanes& out) {
  for (int i = 0; i < kLanes; ++i) {
    HitGeometry g;
    g.a = {geometry.a[0][i], geometry.a[1][i], geometry.a[2][i]};
    if constexpr (Smooth) {  // set only when some lane is smooth (gather_geometry)
      g.n0 = lane_vec(geometry.n, 0, i);
      g.n1 = lane_vec(geometry.n, 1, i);
      g.n2 = lane_vec(geometry.n, 2, i);
      g.planes = {geometry.planes[0][i], geometry.planes[1][i], geometry.planes[2][i]};
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

namespace {
// One planned light's shadow rays and factors for the lanes, instantiated per light type so
// each copy's loops see only their own maths (the point light's are those of the point-only
// renderer, so its bits and its vector code stay as they were).
template <LightType Kind>
long long light_lanes(const SamplePacket& packet, const SurfaceLanes& surfaces,
                      const RenderContext& ctx, std::size_t li, LightLanes& out) {
  const LightSource<float>& light = ctx.plan.sources[li];
  const glm::vec3 towards = -light.direction;  // directional: l, the same at every point
  alignas(64) int lit[kLanes];                 // Embree mask, 64-byte aligned
  alignas(64) double spot[kLanes];             // spot: the cone's factor (light_source.h)
  for (int i = 0; i < kLanes; ++i) {
    const Surface s = surfaces.get(i);
    if constexpr (Kind == LightType::directional) {
      lit[i] = surfaces.hit[i] != 0 && glm::dot(s.n, towards) > 0.0f ? -1 : 0;
    } else {
      lit[i] = surfaces.hit[i] != 0 && glm::dot(s.n, light.position - s.p) > 0.0f ? -1 : 0;
    }
  }
  if constexpr (Kind == LightType::spot) {  // outside the cone: no light, no shadow ray
    for (int i = 0; i < kLanes; ++i) {
      spot[i] = lit[i] != 0 ? spot_at<float>(surfaces.get(i).p, light) : 0.0;
      lit[i] = spot[i] > 0.0 ? lit[i] : 0;
    }
  }
  alignas(64) float vis[kLanes];
  for (int i = 0; i < kLanes; ++i) vis[i] = 1.0f;
  long long rays = 0;
  if (ctx.plan.shadow_rays) {
    RTCRay16 ray;
    for (int i = 0; i < kLanes; ++i) {  // vector code: no call, no branch
      const Surface s = surfaces.get(i);
      if constexpr (Kind == LightType::directional) {  // no end: any surface blocks it
        set_packet_ray(ray, i, shadow_ray_origin(s, packet.t[i], towards), towards);
      } else {
        const glm::vec3 org = shadow_ray_origin(s, packet.t[i], light.position - s.p);
        set_packet_ray(ray, i, org, light.position - org, kShadowRayEnd);
      }
    }
    // Only spheres can find their own origin (self_shadow.h); set_packet_ray left "none". A
    // loop of its own: the call inside the loop above kept it scalar (retrace 12.8 -> 14.2 ms).
    if (ctx.plan.spheres) {
      for (int i = 0; i < kLanes; ++i) {
        ray.id[i] = shadow_ray_id(*ctx.scene, packet.object[i], surfaces.get(i));
      }
    }
    rays = count_set_lanes(lit);
    RTCIntersectContext context = coherent_context();
    rtcOccluded16(lit, ctx.embree->handle(), &context, &ray);
    for (int i = 0; i < kLanes; ++i) {
      vis[i] = lit[i] != 0 && ray.tfar[i] == -std::numeric_limits<float>::infinity() ? 0.0f : 1.0f;
    }
  }
  auto store = [&](int i, const LightFactors<float>& f) {
    const bool on = lit[i] != 0;
    out.diffuse_weight[i] = on ? f.diffuse_weight : 0.0f;
    out.spec_weight[i] = on ? f.spec_weight : 0.0f;
    out.cos_phong[i] = on ? f.cos_phong : 0.0f;
    out.cos_blinn[i] = on ? f.cos_blinn : 0.0f;
  };
  // One copy of the loop per attenuation switch, so each sees a constant and the (1, 0, 0) copy
  // does no attenuation maths.
  auto factors = [&](auto unit_attenuation) {
    constexpr bool kUnit = decltype(unit_attenuation)::value;
    if constexpr (Kind == LightType::point) {
      for (int i = 0; i < kLanes; ++i) {
        const Surface s = surfaces.get(i);
        store(i, light_factors<float>(s.p, s.n, s.v, light.position, light.attenuation, kUnit,
                                      vis[i]));
      }
    } else if constexpr (Kind == LightType::directional) {
      for (int i = 0; i < kLanes; ++i) {
        const Surface s = surfaces.get(i);
        store(i, directional_light_factors<float>(s.n, s.v, light, vis[i]));
      }
    } else {
      for (int i = 0; i < kLanes; ++i) {
        const Surface s = surfaces.get(i);
        store(i, spot_light_factors<float>(s.p, s.n, s.v, light, kUnit, spot[i], vis[i]));
      }
    }
  };
  if (ctx.plan.unit_attenuation[li]) {
    factors(std::true_type{});
  } else if constexpr (Kind != LightType::directional) {
    factors(std::false_type{});
  }
  return rays;
}
}  // namespace

long long packet_light(const SamplePacket& packet, const SurfaceLanes& surfaces,
                       const RenderContext& ctx, std::size_t li, LightLanes& out) {
  switch (ctx.plan.sources[li].type) {
    case LightType::directional:
      return light_lanes<LightType::directional>(packet, surfaces, ctx, li, out);
    case LightType::spot:
      return light_lanes<LightType::spot>(packet, surfaces, ctx, li, out);
    case LightType::point:
      break;
  }
  return light_lanes<LightType::point>(packet, surfaces, ctx, li, out);
}

void store_light(const SamplePacket& packet, int width, const LightLanes& lanes,
                 LightFactorPlane& plane) {
  stream_lanes(packet, width, lanes.diffuse_weight, plane.diffuse_weight.data());
  stream_lanes(packet, width, lanes.spec_weight, plane.spec_weight.data());
  if (plane.unit_cosines) return;  // all 1, not kept (sample_cache.h)
  stream_lanes(packet, width, lanes.cos_phong, plane.cos_phong.data());
  stream_lanes(packet, width, lanes.cos_blinn, plane.cos_blinn.data());
}

}  // namespace gloss
