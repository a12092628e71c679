#pragma once
// Per-sample cache of one image: the primary hit of every sample and, per planned light, the
// geometry factors of the shading contract (shading.h LightFactors). Stored plane by plane
// (plane s holds sample s of every pixel), so progressive passes append planes. Every field is
// its own array (structure of arrays): packets store and re-shading loops read them as vectors.
// Bytes per sample: 20 for the hit + 16 per planned light (8 per environment slot: no cosines)
// + 4 per texel channel (maps).
#include <cstdint>
#include <functional>
#include <vector>

#include "base/uninitialized_buffer.h"
#include "engine/render_context.h"
#include "engine/simd/lanes.h"
#include "scene/camera.h"
#include "shading/shading.h"

namespace gloss {

// Cosines of 1 for up to kLanes lanes: what a slot with unit_cosines reads.
alignas(64) inline constexpr float kUnitCosines[kLanes] = {1, 1, 1, 1, 1, 1, 1, 1,
                                                           1, 1, 1, 1, 1, 1, 1, 1};

// shading.h's LightFactors of one planned light for every pixel of a plane.
struct LightFactorPlane {
  UninitializedBuffer<float> diffuse_weight, spec_weight, cos_phong, cos_blinn;
  // The cosines are 1 everywhere (the environment's slots) and their arrays are empty: 8 bytes
  // per sample and slot neither written by the first pass nor read back.
  bool unit_cosines = false;

  void resize(std::size_t pixels, bool unit = false) {
    unit_cosines = unit;
    diffuse_weight.resize(pixels);
    spec_weight.resize(pixels);
    cos_phong.resize(unit ? 0 : pixels);
    cos_blinn.resize(unit ? 0 : pixels);
  }
  // The cosines of the model from sample `at` on; with unit_cosines, kLanes of them (every
  // reader takes at most kLanes at a time).
  const float* cosine(ShadingModel model, std::size_t at) const {
    if (unit_cosines) return kUnitCosines;
    return (model == ShadingModel::phong ? cos_phong.data() : cos_blinn.data()) + at;
  }
};

struct SamplePlane {
  UninitializedBuffer<std::int32_t> object;  // object index (= geomID), -1 when the ray missed
  UninitializedBuffer<std::uint32_t> prim;   // triangle index; 0 for spheres
  UninitializedBuffer<float> t, u, v;        // hit distance (unit direction) and barycentrics
  std::vector<LightFactorPlane> lights;      // [planned light]
  // What the maps gave each sample (render_plan.h TexturePlan: the multipliers of kd, ka, ks,
  // ke and alpha that vary), one array per channel; empty without maps.
  std::vector<UninitializedBuffer<float>> texels;
};

// Adaptive sampling's extra samples (adaptive_refinement.h): `spp` stratified samples of each
// refined pixel, at the positions uniform sampling with spp samples would use. Entry k * spp + s
// of the plane is sample s of pixels[k]; the plane is one row of entries.
struct RefinedSamples {
  int spp = 0;                        // 0: not traced (no adaptive pass)
  std::vector<std::uint32_t> pixels;  // region pixel indices (y * width + x), ascending
  SamplePlane plane;

  std::size_t entries() const { return pixels.size() * static_cast<std::size_t>(spp); }
};

struct SampleCache {
  int width = 0, height = 0;  // of the region cached: full width, rows [row0, row0 + height)
  int image_height = 0;       // of the whole image (the camera's aspect)
  int row0 = 0;               // first image row of the region
  int target_spp = 1;         // the stratification the sample positions belong to
  std::uint32_t seed = 0;
  CameraFrame camera;            // float: Embree's rays
  CameraBasis<double> camera_d;  // double: the directions hit points are rebuilt with
  std::vector<SamplePlane> planes;
  std::vector<SamplePlane> spare;  // planes of an earlier image, reused to avoid page faults
  // Adaptive sampling: planes holds the pixel centres (target_spp 1) and refined the rest.
  RefinedSamples refined;

  int samples() const { return static_cast<int>(planes.size()); }
  std::size_t pixel_count() const { return static_cast<std::size_t>(width) * height; }
  std::size_t bytes() const;
};

// An empty cache for scene.camera and a width x height image, with the scene's seed, covering
// rows [row0, row0 + rows) (rows < 0: all of them). One-shot renders go band by band to bound
// memory; the progressive engine caches whole images.
SampleCache make_sample_cache(const Scene& scene, int width, int height, int target_spp,
                              int row0 = 0, int rows = -1);

// Restarts the cache for a new image (camera, size or pattern) keeping its memory; drops the
// refined samples.
void reset_sample_cache(SampleCache& cache, const Scene& scene, int width, int height,
                        int target_spp, int row0 = 0, int rows = -1);

// Traces planes [samples(), samples() + count) and computes their light factors. On
// cancellation the new planes are dropped and false is returned; the cache stays consistent.
bool add_samples(SampleCache& cache, const RenderContext& ctx, int count);

// Sizes plane for `pixels` samples, shape.slots light-factor slots and shape.texels texel
// channels; buffers keep their capacity.
void size_plane(SamplePlane& plane, std::size_t pixels, PlaneShape shape);

// Appends count planes sized for the cache and shape (memory of spare planes reused), and drops the
// planes from index first on (to the spares): the bracket of a pass that traces new planes
// (add_samples, trace_single_sample).
void append_planes(SampleCache& cache, PlaneShape shape, int count);
void drop_planes(SampleCache& cache, int first);

// Moves the planes of `from` (a cache no longer needed) and its refined samples' buffers into
// `into`'s spares, so the next image reuses their memory instead of faulting in new pages (a
// full-resolution plane is 33 MB at 1280x720 with one light).
void reclaim_planes(SampleCache& into, SampleCache&& from);

// Sizes every plane for the cache's pixels and shape (before light factors are recomputed
// for another plan).
void size_planes(SampleCache& cache, PlaneShape shape);

// Recomputes the light factors (shadow rays included) of every plane and of the refined
// samples for the context's scene and plan, reusing the primary hits. false when cancelled (the
// factors are then stale).
bool recompute_light_factors(SampleCache& cache, const RenderContext& ctx);

struct SamplePacket;

// Runs visit(packet, plane) -> rays over every plane's packets (band by band on oneTBB
// workers), each with the plane's directions and cached hits loaded. Adds the rays to ctx.rays;
// false when cancelled.
bool visit_cached_samples(SampleCache& cache, const RenderContext& ctx,
                          const std::function<long long(SamplePacket&, SamplePlane&)>& visit);

}  // namespace gloss
