#pragma once
// Why a shadow ray can find the sphere it starts on, and how gloss stops it.
//
// Embree intersects spheres in float from the ray origin: |o - c|^2 - r^2 loses its low bits to
// cancellation when r is large (a ground sphere of radius 1e3 or 1e4), so the root at the ray's
// own origin can come out at a small positive t however far along n_g the origin is pushed, and
// 37-62% of a big ground sphere's lit pixels went black (tests/reference/
// test_sphere_self_shadow.cpp, before this). No offset fixes that at every scale, but geometry
// does: a sphere is convex, so a segment that leaves its outer surface towards the outside
// (ndl > 0) never meets it again. Only from inside can the sphere block its own light, and then
// only where the ray leaves it through the far wall.
//
// So every shadow ray carries in its id the sphere it starts on and from which side, and the
// spheres' occlusion filter drops the hits that cannot be real: every hit on that sphere from
// outside, the entering hits (the origin itself) from inside. Triangles keep the offset alone:
// a flat face cannot meet a ray leaving it.
#include <embree3/rtcore.h>

#include "scene/scene.h"
#include "shading/surface.h"

namespace gloss {

// The id of a shadow ray that starts on no sphere (and of every primary ray).
constexpr unsigned kNoOriginSphere = RTC_INVALID_GEOMETRY_ID;

// The shadow ray id for a hit on scene.objects[object] (-1: none) at surface s (s.ng flipped to
// the viewer's side, as surface.h makes it).
unsigned shadow_ray_id(const Scene& scene, int object, const Surface& s);

// Embree occlusion filter installed on every sphere geometry (embree_scene.cpp).
void drop_origin_sphere_hits(const RTCFilterFunctionNArguments* args);

}  // namespace gloss
