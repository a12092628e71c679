#pragma once
// The document being rendered: camera, lights, materials and objects, all resolved (meshes
// tessellated and loaded). Made by the scene loader, edited by the editor's command layer.
#include <memory>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "scene/camera.h"
#include "scene/environment.h"
#include "scene/geometry/mesh.h"
#include "scene/light.h"
#include "scene/material.h"
#include "scene/object_transform.h"
#include "scene/render_settings.h"

namespace gloss {

enum class ObjectType { sphere, quad, box, teapot, mesh };
const char* to_string(ObjectType type);

// Default crease angle of a `mesh` object, degrees: where a model file has no normals, faces
// meeting at more than this keep a hard edge (a box stays a box), smaller angles are smoothed.
inline constexpr float kDefaultCreaseAngle = 30.0f;

// The parameters an object was made from, kept so a scene saves back as the user wrote it.
struct ShapeParams {
  glm::vec3 center{0.0f};                   // sphere: centre before the transform
  float radius = 1.0f;                      // sphere: radius before the transform, > 0
  glm::vec3 quad[4]{};                      // quad: corners in order around the quad
  glm::vec3 box_min{-0.5f}, box_max{0.5f};  // box: axis-aligned extent before rotate_y
  std::string file;                         // mesh: model path as written in the scene
  std::string group;                        // mesh: the model's material this object holds
  glm::vec3 position{0.0f};                 // box/teapot/mesh: translation after scale and rotate_y
  glm::vec3 scale{1.0f};                    // teapot/mesh: per-axis scale
  float rotate_y = 0.0f;                    // box/teapot/mesh: degrees about +y
  int tessellation = 8;                     // teapot: segments per patch side, 1..64
  bool smooth = true;                       // teapot/mesh: interpolate vertex normals
  float crease_angle = kDefaultCreaseAngle;  // mesh without file normals: degrees, 0..180,
                                             // edges sharper than this stay hard
                                             // (io/model/model_loader.h)
};

// An object as the renderers see it (center, radius, mesh: placed, in world space) and as the
// user wrote it (params, shape, transform, hidden). place_object (scene/geometry/placement.h)
// makes the first from the second; whatever changes the second calls it.
struct Object {
  std::string name;
  ObjectType type = ObjectType::sphere;
  int material = 0;                   // index into Scene::materials
  bool hidden = false;                // not rendered, casts no shadow, cannot be picked
  glm::vec3 center{0.0f};             // sphere, placed: world units
  float radius = 1.0f;                // sphere, placed: > 0
  ShapeParams params;                 // what the geometry was made from (the type's own fields)
  ObjectTransform transform;          // applied after the type's own fields
  std::shared_ptr<const Mesh> shape;  // non-sphere: triangles of the type's own fields
  std::shared_ptr<const Mesh> mesh;   // non-sphere, placed: world-space triangles (== shape
                                      // while the transform is the identity)
};

// A sphere of the given centre and radius (world units), untransformed.
Object sphere_object(const std::string& name, const glm::vec3& center, float radius, int material);

struct Scene {
  Camera camera;
  glm::vec3 background{0.0f};
  glm::vec3 ambient{0.2f};  // A_scene
  std::vector<Light> lights;
  Environment environment;  // none unless the scene file has one
  std::vector<Material> materials;
  std::vector<std::string> material_names;  // parallel to materials
  std::vector<Object> objects;
  RenderSettings render;
  std::string path;  // the file it was loaded from; relative paths resolve against its folder
};

// Index of the material called name, or -1.
int find_material(const Scene& scene, const std::string& name);

// Whether some object of the scene has this type.
bool has_object_type(const Scene& scene, ObjectType type);

// Convex objects cannot shadow themselves; the render plan uses this.
inline bool is_convex(ObjectType type) {
  return type == ObjectType::sphere || type == ObjectType::box || type == ObjectType::quad;
}

}  // namespace gloss
