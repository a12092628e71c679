#pragma once
// Small scenes built in code for the renderer's tests (no loader involved).
#include <cmath>
#include <memory>

#include <glm/geometric.hpp>

#include "scene/geometry/shapes.h"
#include "scene/scene.h"

namespace gloss::test {

inline Material make_material(glm::vec3 ka, glm::vec3 kd, glm::vec3 ks, glm::vec3 ke,
                              float shininess) {
  Material m;
  m.ambient = ka;
  m.diffuse = kd;
  m.specular = ks;
  m.emission = ke;
  m.shininess = shininess;
  return m;
}

inline int add_material(Scene& scene, const std::string& name, const Material& m) {
  scene.materials.push_back(m);
  scene.material_names.push_back(name);
  return static_cast<int>(scene.materials.size()) - 1;
}

inline void add_sphere(Scene& scene, glm::vec3 center, float radius, int material) {
  scene.objects.push_back(
      sphere_object("sphere" + std::to_string(scene.objects.size()), center, radius, material));
}

inline void add_quad(Scene& scene, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d,
                     int material) {
  Object o;
  o.name = "quad" + std::to_string(scene.objects.size());
  o.type = ObjectType::quad;
  o.params.quad[0] = a;
  o.params.quad[1] = b;
  o.params.quad[2] = c;
  o.params.quad[3] = d;
  o.shape = o.mesh = std::make_shared<const Mesh>(make_quad(a, b, c, d));
  o.transform.pivot = 0.25f * (a + b + c + d);
  o.material = material;
  scene.objects.push_back(o);
}

inline PointLight make_light(glm::vec3 position, glm::vec3 diffuse = glm::vec3(1.0f),
                             glm::vec3 specular = glm::vec3(1.0f)) {
  PointLight l;
  l.position = position;
  l.diffuse = diffuse;
  l.specular = specular;
  return l;
}

// The head-on sphere of the hand computation in test_renderer.cpp: unit sphere at the origin,
// eye at (0, 0, 5), odd image size so the centre pixel's ray is the optical axis.
inline Scene head_on_sphere_scene() {
  Scene scene;
  scene.camera.eye = {0, 0, 5};
  scene.camera.target = {0, 0, 0};
  scene.camera.up = {0, 1, 0};
  scene.camera.fov_y = 40;
  scene.ambient = glm::vec3(0.2f);
  scene.background = {0.0f, 0.0f, 0.0f};
  const int m = add_material(scene, "test",
                             make_material({0.1f, 0.2f, 0.3f}, {0.5f, 0.4f, 0.3f}, glm::vec3(0.8f),
                                           {0.01f, 0.0f, 0.0f}, 10.0f));
  add_sphere(scene, {0, 0, 0}, 1.0f, m);
  PointLight light = make_light({0, 3, 5}, glm::vec3(1.0f), {1.0f, 0.5f, 0.25f});
  light.ambient = glm::vec3(0.1f);
  light.attenuation = {1.0f, 0.1f, 0.01f};
  scene.lights.push_back(light);
  scene.render.width = 101;
  scene.render.height = 101;
  scene.render.spp = 1;
  return scene;
}

// The head-on sphere seen from above over a floor quad, background visible: every render stage
// has work (primary misses, shadow rays fewer than primaries). 80 x 60 at 4 spp.
inline Scene sphere_on_floor_scene() {
  Scene scene = head_on_sphere_scene();
  scene.camera.eye = {0, 1.5f, 5};
  scene.camera.target = {0, -0.5f, 0};
  const int floor = add_material(
      scene, "floor",
      make_material(glm::vec3(0.1f), glm::vec3(0.6f), glm::vec3(0.2f), glm::vec3(0.0f), 8));
  add_quad(scene, {-2, -1, 2}, {2, -1, 2}, {2, -1, -2}, {-2, -1, -2}, floor);
  scene.render.width = 80;
  scene.render.height = 60;
  scene.render.spp = 4;
  return scene;
}

// A floor seen straight from above with a light straight above, and a sphere between them whose
// shadow falls on the centre of the image (33 x 33, 1 spp: the centre pixel's ray goes straight
// down). Object 0 is the sphere, 1 the floor. With the sphere away (or hidden) the centre is
// the lit floor: ka A + kd Ld (N.L = 1, attenuation 1, no specular) = 0.2 x 0.2 + 0.5 = 0.54.
inline Scene shadowing_sphere_scene() {
  Scene scene;
  scene.camera.eye = {0, 5, 0};
  scene.camera.target = {0, 0, 0};
  scene.camera.up = {0, 0, -1};
  scene.camera.fov_y = 60;
  scene.ambient = glm::vec3(0.2f);
  const int ball = add_material(
      scene, "ball",
      make_material(glm::vec3(0.1f), {0.9f, 0.1f, 0.1f}, glm::vec3(0.0f), glm::vec3(0.0f), 10.0f));
  const int floor = add_material(
      scene, "floor",
      make_material(glm::vec3(0.2f), glm::vec3(0.5f), glm::vec3(0.0f), glm::vec3(0.0f), 10.0f));
  add_sphere(scene, {0, 1, 0}, 0.5f, ball);
  add_quad(scene, {-4, 0, 4}, {4, 0, 4}, {4, 0, -4}, {-4, 0, -4}, floor);
  scene.lights.push_back(make_light({0, 4, 0}));
  scene.render.width = 33;
  scene.render.height = 33;
  scene.render.spp = 1;
  return scene;
}

// A unit UV sphere of `segments` around and `rings` from pole to pole, unit radial normals.
inline Mesh uv_sphere(int segments, int rings) {
  const double pi = 3.14159265358979323846;
  Mesh m;
  for (int r = 0; r <= rings; ++r) {
    for (int s = 0; s <= segments; ++s) {
      const double theta = pi * r / rings, phi = 2 * pi * s / segments;
      const glm::vec3 p(static_cast<float>(std::sin(theta) * std::cos(phi)),
                        static_cast<float>(std::cos(theta)),
                        static_cast<float>(std::sin(theta) * std::sin(phi)));
      m.positions.push_back(p);
      m.normals.push_back(glm::normalize(p));
    }
  }
  const auto at = [&](int r, int s) { return static_cast<unsigned>(r * (segments + 1) + s); };
  for (int r = 0; r < rings; ++r) {
    for (int s = 0; s < segments; ++s) {
      // Outward winding; the pole rows' zero-area triangles left out.
      if (r > 0) m.triangles.push_back({at(r, s), at(r, s + 1), at(r + 1, s)});
      if (r < rings - 1) m.triangles.push_back({at(r, s + 1), at(r + 1, s + 1), at(r + 1, s)});
    }
  }
  return m;
}

// A coarse smooth mesh, a unit UV sphere of 12 x 6 faces with radial normals, lit from the right
// and a little behind (its terminator crosses the visible side), kd 0.5 matte, 128 x 128, shadows
// on: the shadow terminator's scene (tests/reference/test_shadow_terminator.cpp, raster too).
inline Scene faceted_sphere_scene() {
  Scene scene;
  scene.camera.eye = {0, 0.4f, 3.2f};
  scene.camera.target = {0, 0, 0};
  scene.camera.up = {0, 1, 0};
  scene.camera.fov_y = 45;
  scene.ambient = glm::vec3(0.0f);
  add_material(
      scene, "grey",
      make_material(glm::vec3(0.0f), glm::vec3(0.5f), glm::vec3(0.0f), glm::vec3(0.0f), 1));
  // From the right and a little behind: the terminator crosses the visible side.
  scene.lights.push_back(make_light({30, 6, -12}));
  Object o;
  o.name = "faceted";
  o.type = ObjectType::mesh;
  o.shape = o.mesh = std::make_shared<const Mesh>(uv_sphere(12, 6));
  scene.objects.push_back(o);
  scene.render.width = 128;
  scene.render.height = 128;
  scene.render.shadows = true;
  return scene;
}

}  // namespace gloss::test
