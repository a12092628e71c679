#pragma once
// The MapFrames of a packet's hits (shading/map_frame.h) by component, for the lane forms of the
// map lookups (map_lanes.h, normal_map_lanes.h; docs/engine.md, "Maps in lanes"): each lane's
// triangle corners are fetched, then one loop of selects over the lanes interpolates (u, v) and
// the tangent, sizes the ray cone's footprint, and finds the side the surface was modelled
// facing, the same operations in the same order as mesh_map_frame<float> (up to FMA
// contraction, which can round a (u, v) an ulp apart); log2 of the footprint per lane with the
// C library's log2f, as map_values. Sphere hits go through sphere_map_frame per lane.
#include <cstdint>

#include "engine/simd/lanes.h"
#include "engine/trace/normal_map_lanes.h"

namespace gloss {

struct SamplePacket;  // sample_packet.h
struct SurfaceLanes;
struct Scene;  // scene/scene.h

struct MapFrameLanes {
  // Each (u, v) set and log2 of its footprint (what map_values reads a map of that set with).
  alignas(64) float u[2][kLanes], v[2][kLanes], log_footprint[2][kLanes];
  TangentLanes tangents;
};

// The frames of the lanes in mask (hits whose material has maps). spread: the ray cone's
// (texture/footprint.h cone_spread).
void map_frame_lanes(const SamplePacket& packet, const Scene& scene, const SurfaceLanes& surfaces,
                     float spread, std::uint32_t mask, MapFrameLanes& out);

}  // namespace gloss
