#pragma once
// One sample of the reference path (reference's own): the camera ray, the hit recomputed in the
// scalar type T, every light and the environment evaluated through shading/ and recorded for the
// pixel inspector when asked. render_reference (reference_renderer.cpp) and the PixelInspector
// (pixel_inspection.cpp) both shade through shade_sample.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include <embree3/rtcore.h>

#include "engine/trace/embree_scene.h"
#include "engine/trace/self_shadow.h"
#include "physical/microfacet.h"
#include "physical/reference_brdf.h"
#include "reference/pixel_inspection.h"
#include "reference/reference_environment.h"
#include "reference/reference_hit.h"
#include "reference/reference_maps.h"
#include "scene/camera.h"
#include "shading/light_source.h"
#include "shading/sampling.h"
#include "shading/shading.h"
#include "shading/surface.h"
#include "shading/total.h"

namespace gloss::reference_detail {

template <class T>
using Vec3 = glm::tvec3<T>;

// What one sample saw, for the edge mask of ReferenceOptions::edges.
struct SampleKey {
  std::int32_t object = -1;         // -1: missed
  std::uint64_t shadowed = 0;       // bit i % 64 set when light i was blocked
  std::uint64_t outside_cone = 0;   // bit i % 64 set when p is outside spot i's hard-edged cone
  bool mesh = false, flat = false;  // a triangle mesh; one without vertex normals
  glm::vec3 p{0.0f};                // hit point
  glm::vec3 ng{0.0f};               // geometric normal, viewer's side
};

// A hit or shadow flip between a and b. Within one mesh: b off a's tangent plane (the chord
// leaves the plane at more than 14.5 degrees: another part of the mesh behind a silhouette of
// it), or, on a flat mesh, another face. Spheres are convex: the object decides.
inline bool discontinuous(const SampleKey& a, const SampleKey& b) {
  if (a.object != b.object || a.shadowed != b.shadowed) return true;
  if (a.outside_cone != b.outside_cone) return true;  // a hard cone edge, like a shadow edge
  if (a.object < 0 || !a.mesh) return false;
  const glm::vec3 chord = b.p - a.p;
  const float len = glm::length(chord);
  if (std::abs(glm::dot(a.ng, chord)) > 0.25f * len) return true;
  return a.flat && glm::dot(a.ng, b.ng) < 0.9999f;
}

// Per-pixel sums over samples, in T.
template <class T>
struct PixelSums {
  Vec3<T> emissive{0}, ambient{0}, diffuse{0}, specular{0};
  int misses = 0;
  Vec3<T> sky{0};  // the environment towards the samples that missed (as_background)
};

template <class T>
struct Job {
  const Scene* scene = nullptr;
  RTCScene rtc = nullptr;
  CameraBasis<T> camera;  // camera.h's formula evaluated in T
  int width = 0, height = 0, spp = 1;
  PowMode pow = PowMode::exact;
  MapFilter filter = MapFilter::trilinear;
  bool gouraud = false;
  T fov_y = T(45);                      // degrees: the ray cone's spread (texture/footprint.h)
  Vec3<T> ambient_light{0};             // A_scene + sum_i La_i
  std::vector<LightSource<T>> sources;  // per scene light, resolved in T (light_source.h)
  const ReferenceEnvironment* environment = nullptr;  // the scene's, when it has one
  // Per material, its physical reference's BRDF when ReferenceOptions::physical asks for it.
  std::vector<std::optional<ReferenceBrdf>> physical;
};

// Where a missed sample's total comes from: the environment when it is the background.
template <class T>
bool sky_shown(const Job<T>& job) {
  return job.environment != nullptr && job.environment->present() &&
         job.scene->environment.as_background;
}

// The environment's terms at hit h (reference_environment.h), added to sum and recorded.
template <class T>
void shade_environment(const Job<T>& job, int object, const ReferenceHit<T>& h, const Material& m,
                       std::uint32_t seed, PixelSums<T>& sum, PixelBreakdown* record) {
  const Scene& scene = *job.scene;
  const Surface s = float_surface(h);
  const unsigned id = shadow_ray_id(scene, object, s);
  auto blocked = [&](const glm::dvec3& w) {
    const glm::vec3 origin = shadow_ray_origin(s, static_cast<float>(h.t), glm::vec3(w));
    RTCRay ray;
    ray.org_x = origin.x;
    ray.org_y = origin.y;
    ray.org_z = origin.z;
    ray.dir_x = static_cast<float>(w.x);
    ray.dir_y = static_cast<float>(w.y);
    ray.dir_z = static_cast<float>(w.z);
    ray.tnear = 0.0f;
    ray.tfar = std::numeric_limits<float>::infinity();
    ray.time = 0.0f;
    ray.mask = 0xffffffffu;
    ray.id = id;
    ray.flags = 0;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    rtcOccluded1(job.rtc, &context, &ray);
    return ray.tfar == -std::numeric_limits<float>::infinity();
  };
  const ReferenceEnvironment::Reading e =
      job.environment->at(glm::dvec3(h.n), glm::dvec3(h.v), m.shininess, scene.render.model,
                          m.diffuse != glm::vec3(0.0f), m.specular != glm::vec3(0.0f),
                          scene.render.shadows, seed, blocked);
  sum.diffuse += Vec3<T>(m.diffuse) * Vec3<T>(e.diffuse);
  sum.specular += Vec3<T>(m.specular) * Vec3<T>(e.specular);
  if (record != nullptr) {
    EnvironmentBreakdown& out = record->environment;
    out.present = true;
    out.estimated = e.estimated;
    out.diffuse = glm::dvec3(m.diffuse) * e.diffuse;
    out.specular = glm::dvec3(m.specular) * e.specular;
    out.diffuse_error = glm::dvec3(m.diffuse) * e.diffuse_error;
    out.specular_error = glm::dvec3(m.specular) * e.specular_error;
    out.unshadowed_diffuse = glm::dvec3(m.diffuse) * e.unshadowed_diffuse;
    out.unshadowed_specular = glm::dvec3(m.specular) * e.unshadowed_specular;
    out.visibility = e.visibility;
  }
}

// The spec's shadow test for one light from a hit: the segment from the offset origin
// (surface.h shadow_ray_origin, shared with the fast renderer) to just short of the light, or
// for a directional light the ray towards it without end. object: the index of the hit's
// object (its sphere is left out of its own shadow test, engine/trace/self_shadow.h).
template <class T>
bool occluded(const Job<T>& job, int object, const ReferenceHit<T>& h,
              const LightSource<T>& light) {
  const Surface s = float_surface(h);
  const bool directional = light.type == LightType::directional;
  const glm::vec3 towards =
      directional ? -glm::vec3(light.direction) : glm::vec3(light.position) - s.p;
  const glm::vec3 org = shadow_ray_origin(s, static_cast<float>(h.t), towards);
  const glm::vec3 dir = directional ? towards : glm::vec3(light.position) - org;
  RTCRay ray;
  ray.org_x = org.x;
  ray.org_y = org.y;
  ray.org_z = org.z;
  ray.dir_x = dir.x;
  ray.dir_y = dir.y;
  ray.dir_z = dir.z;
  ray.tnear = 0.0f;
  // As the fast renderer: a light resting on a surface still lights it.
  ray.tfar = directional ? std::numeric_limits<float>::infinity() : 1.0f - 1e-5f;
  ray.time = 0.0f;
  ray.mask = 0xffffffffu;
  ray.id = shadow_ray_id(*job.scene, object, s);
  ray.flags = 0;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  rtcOccluded1(job.rtc, &context, &ray);
  return ray.tfar == -std::numeric_limits<float>::infinity();
}

// The unshadowed diffuse and specular weights of one light at one point (shading.h), the
// specular one including c^alpha: diffuse = kd Ld dw, specular = ks Ls sw (times normalisation).
// Returns the factors they came from (the pixel inspector shows them).
template <class T>
LightFactors<T> light_weights(const Job<T>& job, const Vec3<T>& p, const Vec3<T>& n,
                              const Vec3<T>& v, const LightSource<T>& light, T alpha, T& dw,
                              T& sw) {
  const LightFactors<T> f = source_factors<T>(p, n, v, light, spot_at<T>(p, light), T(1));
  dw = f.diffuse_weight;
  sw = f.spec_weight * specular_power<T>(model_cosine(f, job.scene->render.model), alpha, job.pow);
  return f;
}

// A light's physical-reference terms at a hit (ReferenceOptions::physical), unshadowed:
// pi f(l, v) Ld ndl att spot, split into the dielectric base (diffuse) and the microfacet lobe
// (specular). ndl att spot comes from the contract's factors (light_source.h), so ndl <= 0, d = 0
// and a point outside a spot's cone add nothing as for Phong; f is 0 where n.v <= 0 (a shading
// normal turned away from the eye).
template <class T>
void physical_terms(const ReferenceBrdf& brdf, const Vec3<T>& p, const Vec3<T>& n, const Vec3<T>& v,
                    const LightSource<T>& light, const Light& colours, glm::dvec3& diffuse,
                    glm::dvec3& specular) {
  const LightFactors<T> f = source_factors<T>(p, n, v, light, spot_at<T>(p, light), T(1));
  diffuse = specular = glm::dvec3(0.0);
  if (!(f.diffuse_weight > T(0))) return;
  const glm::dvec3 l = light.type == LightType::directional
                           ? -glm::normalize(glm::dvec3(light.direction))
                           : glm::normalize(glm::dvec3(light.position) - glm::dvec3(p));
  const BrdfValue value =
      evaluate_brdf(brdf, glm::normalize(glm::dvec3(n)), l, glm::normalize(glm::dvec3(v)));
  const glm::dvec3 scale = glm::dvec3(colours.diffuse) * (kPi * double(f.diffuse_weight));
  diffuse = value.diffuse * scale;
  specular = value.specular * scale;
}

// Gouraud weights at a mesh hit: the corners' unshadowed weights interpolated with the
// barycentrics (clamped at 0: barycentrics of a hit on an edge can round below 0).
template <class T>
void gouraud_weights(const Job<T>& job, const Mesh& mesh, std::uint32_t prim,
                     const ReferenceHit<T>& h, const LightSource<T>& light, T alpha, T& dw, T& sw) {
  const glm::uvec3 tri = mesh.triangles[prim];
  dw = sw = T(0);
  for (int k = 0; k < 3; ++k) {
    const unsigned index = tri[k];
    const Vec3<T> p(mesh.positions[index]);
    Vec3<T> n = h.ng;  // flat meshes: the face normal, already on the viewer's side
    if (mesh.smooth()) {
      n = glm::normalize(Vec3<T>(mesh.normals[index]));
      if (h.flipped) n = -n;
    }
    const Vec3<T> v = glm::normalize(job.camera.eye - p);
    T d = 0, s = 0;
    light_weights(job, p, n, v, light, alpha, d, s);
    dw += h.b[k] * d;
    sw += h.b[k] * s;
  }
  dw = std::max(dw, T(0));
  sw = std::max(sw, T(0));
}

// The pixel inspector's record of one light, filled beside the sums (record mode only): the
// factors of the contract that the sums do not keep. The shadow test is made whatever ndl is,
// as the contract defines vis; it changes nothing when ndl <= 0.
template <class T>
void record_light(const Job<T>& job, int object, const ReferenceHit<T>& h,
                  const LightSource<T>& light, T alpha, LightBreakdown& out) {
  out.type = light.type;
  out.spot = double(spot_at<T>(h.p, light));
  T d = 0;
  if (light.type == LightType::directional) {
    out.ndl = double(-glm::dot(h.n, light.direction));
  } else {
    const Vec3<T> to_light = light.position - h.p;
    d = glm::length(to_light);
    out.distance = double(d);
    out.ndl = d > T(0) ? double(glm::dot(h.n, to_light) / d) : 0.0;
    out.attenuation = double(attenuation(light.attenuation, d));
  }
  T dw = 0, sw = 0;
  const LightFactors<T> f = light_weights(job, h.p, h.n, h.v, light, alpha, dw, sw);
  const T c = model_cosine(f, job.scene->render.model);
  out.cosine = double(c);
  out.cosine_power = double(specular_power<T>(c, alpha, job.pow));
  const bool reaches = light.type == LightType::directional || d > T(0);
  const bool blocked = job.scene->render.shadows && reaches && occluded(job, object, h, light);
  out.visibility = blocked ? 0.0 : 1.0;
}

// The fast renderer's condition for a shadow ray, in T: ndl > 0 (from the unnormalised l of a
// point or spot light) and, for a spot, inside the cone.
template <class T>
bool faces_light(const ReferenceHit<T>& h, const LightSource<T>& light) {
  if (light.type == LightType::directional) return glm::dot(h.n, light.direction) < T(0);
  return glm::dot(h.n, light.position - h.p) > T(0) && spot_at<T>(h.p, light) > 0;
}

// One sample: trace, recompute the hit in T, shade every light, add to sum. record (the pixel
// inspector, one sample): also keeps what each light's factors were.
template <class T>
void shade_sample(const Job<T>& job, int x, int y, int s, int count, PixelSums<T>& sum,
                  SampleKey& key, PixelBreakdown* record = nullptr) {
  const Scene& scene = *job.scene;
  const SampleOffset o = sample_offset(scene.render.seed, x, y, s, count);
  const Vec3<T> dir =
      camera_direction<T>(job.camera, T(x) + T(o.dx), T(y) + T(o.dy), job.width, job.height);
  RTCRayHit rh;
  rh.ray.org_x = static_cast<float>(job.camera.eye.x);
  rh.ray.org_y = static_cast<float>(job.camera.eye.y);
  rh.ray.org_z = static_cast<float>(job.camera.eye.z);
  rh.ray.dir_x = static_cast<float>(dir.x);
  rh.ray.dir_y = static_cast<float>(dir.y);
  rh.ray.dir_z = static_cast<float>(dir.z);
  rh.ray.tnear = 0.0f;
  rh.ray.tfar = std::numeric_limits<float>::infinity();
  rh.ray.time = 0.0f;
  rh.ray.mask = 0xffffffffu;
  rh.ray.id = kNoOriginSphere;
  rh.ray.flags = 0;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  rtcIntersect1(job.rtc, &context, &rh);
  key = SampleKey{};
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) {
    ++sum.misses;
    if (sky_shown(job)) sum.sky += Vec3<T>(job.environment->radiance(glm::dvec3(dir)));
    return;
  }
  const Object& object = scene.objects[rh.hit.geomID];
  const bool is_mesh = object.type != ObjectType::sphere;
  ReferenceHit<T> h = is_mesh
                          ? triangle_reference_hit<T>(*object.mesh, rh.hit.primID, job.camera.eye,
                                                      dir, T(rh.ray.tfar), T(rh.hit.u), T(rh.hit.v))
                          : sphere_reference_hit<T>(object, job.camera.eye, dir, T(rh.ray.tfar));
  const Material& m = scene.materials[static_cast<std::size_t>(object.material)];
  MapValues<T> maps;  // 1, and n unchanged, where the material has no map
  MapFrame<T> frame;
  if (m.textured()) {
    maps =
        hit_maps(job.fov_y, job.height, job.filter, object, rh.hit.primID, dir, count, h, m, frame);
    h.n = maps.n;
  }
  key.object = static_cast<std::int32_t>(rh.hit.geomID);
  key.mesh = is_mesh;
  key.flat = is_mesh && !object.mesh->smooth();
  key.p = glm::vec3(h.p);
  key.ng = glm::vec3(h.ng);
  if (record != nullptr) {
    record->hit = true;
    record->object = key.object;
    record->position = glm::dvec3(h.p);
    record->normal = glm::dvec3(h.n);
    record->view = glm::dvec3(h.v);
    record->lights.assign(scene.lights.size(), LightBreakdown{});
  }

  const T alpha = T(m.shininess) * maps.alpha;
  const Vec3<T> ka = Vec3<T>(m.ambient) * maps.ka, kd = Vec3<T>(m.diffuse) * maps.kd,
                ks = Vec3<T>(m.specular) * maps.ks, ke = Vec3<T>(m.emission) * maps.ke;
  const T norm =
      scene.render.energy_normalize ? energy_normalization<T>(scene.render.model, alpha) : T(1);
  sum.emissive += ke;
  sum.ambient += ka * job.ambient_light;
  if (record != nullptr) {
    if (m.textured()) record_maps(m, frame, maps, *record);
    record->material = object.material;
    record->alpha = double(alpha);
    record->energy_factor = double(norm);
  }
  const std::optional<ReferenceBrdf>& physical =
      job.physical.empty() ? std::optional<ReferenceBrdf>()
                           : job.physical[static_cast<std::size_t>(object.material)];
  for (std::size_t i = 0; i < scene.lights.size(); ++i) {
    const Light& colours = scene.lights[i];
    const LightSource<T>& light = job.sources[i];
    if (physical) {
      if (!faces_light(h, light)) continue;
      if (scene.render.shadows && occluded(job, key.object, h, light)) {
        key.shadowed |= std::uint64_t(1) << (i % 64);
        continue;
      }
      glm::dvec3 diffuse, specular;
      physical_terms(*physical, h.p, h.n, h.v, light, colours, diffuse, specular);
      sum.diffuse += Vec3<T>(diffuse);
      sum.specular += Vec3<T>(specular);
      continue;
    }
    if (light.type == LightType::spot && !light.smooth_edge && !(spot_at<T>(h.p, light) > T(0))) {
      key.outside_cone |= std::uint64_t(1) << (i % 64);
    }
    if (record != nullptr) record_light(job, key.object, h, light, alpha, record->lights[i]);
    T dw = 0, sw = 0;
    bool lit_side;
    if (job.gouraud && is_mesh) {
      gouraud_weights(job, *object.mesh, rh.hit.primID, h, light, alpha, dw, sw);
      lit_side = dw > T(0) || sw > T(0);
    } else {
      lit_side = faces_light(h, light);
      if (lit_side) light_weights(job, h.p, h.n, h.v, light, alpha, dw, sw);
    }
    if (!lit_side) continue;
    if (scene.render.shadows && occluded(job, key.object, h, light)) {
      key.shadowed |= std::uint64_t(1) << (i % 64);
      continue;  // vis = 0
    }
    sum.diffuse += kd * Vec3<T>(colours.diffuse) * dw;
    sum.specular += ks * Vec3<T>(colours.specular) * (sw * norm);
    if (record != nullptr) {  // the same products, kept apart (the sums above stay as they were)
      record->lights[i].diffuse = glm::dvec3(kd * Vec3<T>(colours.diffuse) * dw);
      record->lights[i].specular = glm::dvec3(ks * Vec3<T>(colours.specular) * (sw * norm));
    }
  }
  if (job.environment != nullptr && job.environment->present()) {
    const std::uint32_t seed =
        mix_bits(scene.render.seed ^ mix_bits(static_cast<std::uint32_t>(x) ^
                                              mix_bits(static_cast<std::uint32_t>(y) ^
                                                       mix_bits(static_cast<std::uint32_t>(s)))));
    Material shaded = m;  // the constants times what the maps gave here
    shaded.diffuse = glm::vec3(kd);
    shaded.specular = glm::vec3(ks);
    shaded.shininess = static_cast<float>(alpha);
    shade_environment(job, key.object, h, shaded, seed, sum, record);
  }
}

// The background part of a pixel's total over `count` samples: the sky or the colour.
template <class T>
Vec3<T> missed_background(const Job<T>& job, const PixelSums<T>& sum, T inv_count) {
  if (sky_shown(job)) return sum.sky * inv_count;
  return Vec3<T>(job.scene->background) * (T(sum.misses) * inv_count);
}

template <class T>
Job<T> make_job(const Scene& scene, RTCScene rtc, int spp, PowMode pow) {
  Job<T> job;
  job.scene = &scene;
  job.rtc = rtc;
  job.width = scene.render.width;
  job.height = scene.render.height;
  job.spp = spp;
  job.pow = pow;
  job.filter = scene.render.map_filter;
  job.fov_y = T(scene.camera.fov_y);
  job.camera = make_camera_basis<T>(scene.camera, job.width, job.height);
  job.ambient_light = Vec3<T>(scene.ambient);
  for (const Light& light : scene.lights) {
    job.ambient_light += Vec3<T>(light.ambient);
    job.sources.push_back(make_light_source<T>(light, scene.camera));
  }
  return job;
}

}  // namespace gloss::reference_detail
