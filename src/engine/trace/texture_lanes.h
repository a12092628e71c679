#pragma once
// The materials' maps at a packet's hits (docs/spec/shading.md, "Textures"; render_plan.h
// TexturePlan): per lane the multipliers of kd, ka, ks, ke and alpha its material's maps give
// there, and the shading normal its normal or bump map makes (the light factors then see it).
// Each lane whose material has maps goes through the contract's functions
// (shading/hit_textures.h, shading/map_frame.h) as the reference path does, in float; lanes of
// untextured materials get 1 and keep their normal.
#include <cstddef>

#include "engine/render_context.h"
#include "engine/simd/lanes.h"
#include "engine/trace/sample_cache.h"

namespace gloss {

struct SamplePacket;  // sample_packet.h, which calls these from shade_sample
struct SurfaceLanes;

// The most texel channels a plan can have: kd, ka, ks, ke (3 each) and alpha.
inline constexpr int kMaxTexelChannels = 13;

struct TexelLanes {
  alignas(64) float channel[kMaxTexelChannels][kLanes];
};

// Fills out's plan channels for the packet's lanes and turns surfaces' normals (n only; n_g
// and the points stay). spp: the samples per pixel the packet's samples belong to (each a
// 1 / sqrt(spp) share of its pixel's footprint, texture/footprint.h).
void texture_lanes(const SamplePacket& packet, const SampleCache& cache, const RenderContext& ctx,
                   int spp, SurfaceLanes& surfaces, TexelLanes& out);

// The packet's surfaces with the normal and bump maps applied (what shade_sample's lights see),
// for stages that rebuild surfaces from cached hits on their own (the environment's).
void mapped_surfaces(const SamplePacket& packet, const SampleCache& cache, const RenderContext& ctx,
                     const SamplePlane& plane, SurfaceLanes& surfaces);

// Every channel 1 (the lanes of a packet that hit nothing, or no textured material).
void unit_texels(std::size_t channels, TexelLanes& out);

// The maps sampled again at every cached sample (planes and refined samples) from its cached
// hit, no rays: a `texture` edit (another colour or shininess map, other map settings, another
// filter). Normal maps are left alone (they move n: a `light` edit). false when cancelled.
bool resample_textures(SampleCache& cache, const RenderContext& ctx);

// The packet's texel lanes to and from a cache plane (width: the plane's row length).
void store_texels(const SamplePacket& packet, int width, const TexelLanes& lanes,
                  SamplePlane& plane);
void load_texels(const SamplePacket& packet, int width, const SamplePlane& plane,
                 TexelLanes& lanes);

}  // namespace gloss
