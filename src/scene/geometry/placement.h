#pragma once
// An object's transform (scene/object_transform.h) as maths, and the one function that applies
// it: p' = pivot + translate + Rz Ry Rx S (p - pivot), rotations in degrees about x first, in
// double and rounded once to float. A sphere stays analytic: its centre moves, its radius scales
// by |s| (a sphere takes a uniform scale only; validation refuses another).
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "scene/scene.h"

namespace gloss {

// Rz Ry Rx: rotate x first, then y, then z; degrees.
glm::dmat3 rotation_matrix(const glm::vec3& degrees);
// Rz Ry Rx S.
glm::dmat3 linear_part(const ObjectTransform& t);
// p placed by t.
glm::dvec3 place_point(const ObjectTransform& t, const glm::dvec3& p);
// Whether t leaves every point where it is (pivot aside).
bool is_identity(const ObjectTransform& t);

// Euler angles (degrees, x first, as rotation_matrix takes them) of the rotation r, the solution
// nearest near (each angle moved by whole turns, and of the two solutions of a non-degenerate r
// the nearer), so that a gizmo drag turns the numbers smoothly.
glm::vec3 euler_degrees(const glm::dmat3& r, const glm::vec3& near = glm::vec3(0.0f));

// The object's own centre, before the transform: a sphere's center, a quad's centroid, a box's,
// mesh's or teapot's bounding-box centre (of shape).
glm::vec3 own_centre(const Object& object);

// Makes object's placed geometry (center and radius, or mesh) from its own (params.center and
// params.radius, or shape) and its transform; an unset pivot first follows own_centre. An object
// whose shape is null takes its mesh as the shape (objects made in code). Identity transforms
// share the shape's mesh and copy the sphere exactly, so old scenes render bit for bit as before.
void place_object(Object& object);

// World-space bounds of the placed object (a sphere's centre +- radius); false when it has none.
bool object_bounds(const Object& object, glm::vec3& lo, glm::vec3& hi);

}  // namespace gloss
