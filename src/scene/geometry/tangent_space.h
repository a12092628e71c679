#pragma once
// Tangents for normal maps as MikkTSpace defines them (Morten Mikkelsen, "Simulation of
// Wrinkled Surfaces Revisited", 2008, and the algorithm of his mikktspace.c as Blender and the
// glTF specification use it): the convention normal maps are baked in. Written here from that
// description (no Debian package ships it): corners welded by position, normal and (u, v);
// per triangle the (u, v) gradient directions dP/du, dP/dv and its orientation (the sign of its
// (u, v) area); groups of triangles around a vertex joined across shared edges when their
// orientations agree; per group the directions made perpendicular to the vertex normal and
// averaged with the angle of each triangle's corner as weight. The tangent is the averaged dP/du,
// the handedness +1 for orientation-preserving groups and -1 for mirrored ones.
#include "scene/geometry/mesh.h"

namespace gloss {

// Sets mesh.tangents from (u, v) set 0, splitting vertices whose corners get different tangents
// (positions, normals and (u, v) are copied; triangles keep their order and corner order). A
// mesh without (u, v) is left as it is. Flat meshes use each triangle's face normal.
void generate_tangents(Mesh& mesh);

}  // namespace gloss
