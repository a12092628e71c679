#pragma once
// New objects made ready to add to a scene (object_commands.h's AddObjects): a primitive (sphere,
// quad, box, teapot) or a model file's parts. Each is scaled to the scene, set down with its
// lowest point on the surface below it (a ray query through the scene's Embree twin, else the
// scene's bounds) and put beside, not inside, the visible objects already there; its own fields
// (a sphere's center, a box's or a model's position) carry that placement, its transform stays
// the identity. docs/editor.md, "Objects", says what a user sees.
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "editor/model/document/object_commands.h"
#include "scene/scene.h"

namespace gloss {

// The size (largest side, world units) of a new object in scene: the median largest side of its
// visible solid objects (not flat ones such as floors and walls), at most 0.35 of the scene's
// largest side; without solid objects 0.3 of that side; 2 in an empty scene.
float new_object_size(const Scene& scene);

// The translation that moves an object whose own bounds are lo..hi (world units) to its place:
// its lowest point on the surface below it, its box clear of every visible object's box by a
// tenth of its largest side (the surface it rests on aside), as near the camera target as such a
// place is. Candidates lie on a grid around the target, nearest first, distances along the view
// counting three times (beside the objects as the camera sees them, not in front of or behind
// them), and places the camera sees before others (centre in the image; the centre and most of the
// upper part reach the eye; the centre of no solid object hidden behind it); the
// surface under a candidate is the highest hit of rays cast straight down at its footprint's
// corners and centre from above where it would rest, and a candidate whose rays meet anything but
// the top of an object at least as wide as its footprint (the shoulder of a sphere, a post) is
// passed over; with no surface below, the scene's lowest point. In an empty scene the object is
// centred on the camera target.
glm::vec3 placement_offset(const Scene& scene, const glm::vec3& lo, const glm::vec3& hi);

// A new primitive of type (sphere, quad, box or teapot; not mesh) with its own grey material
// (the material defaults), named after its type ("sphere", "box 2" ...). A quad stands upright
// facing the camera.
AddObjects primitive_objects(const Scene& scene, ObjectType type);

// The parts of the model file at path (model_loader.h), one object per material, each with the
// file's material (parts with none share the grey "default"), scaled together to
// new_object_size and placed together. Throws InputError naming the file. warnings: the
// loader's (degenerate triangles dropped ...); notes: how its glTF materials were read (the
// fitted Phong or assimp's rule, with both errors).
AddObjects model_objects(const Scene& scene, const std::string& path,
                         std::vector<std::string>* warnings = nullptr,
                         std::vector<std::string>* notes = nullptr);

}  // namespace gloss
