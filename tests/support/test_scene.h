#pragma once
// A small scene built in code for the editor's unit tests: two spheres with their own materials,
// two lights, every value chosen by hand.
#include "scene/scene.h"

namespace gloss::test {

inline Scene two_sphere_scene() {
  Scene scene;
  scene.camera.eye = {0.0f, 1.0f, 6.0f};
  scene.camera.target = {0.0f, 0.0f, 0.0f};
  scene.camera.fov_y = 40.0f;
  scene.background = {0.1f, 0.1f, 0.1f};
  scene.ambient = {0.2f, 0.2f, 0.2f};
  PointLight a;
  a.position = {4.0f, 4.0f, 4.0f};
  PointLight b;
  b.position = {-4.0f, 2.0f, 1.0f};
  b.diffuse = {0.5f, 0.5f, 0.5f};
  scene.lights = {a, b};
  Material red;
  red.ambient = {0.1f, 0.0f, 0.0f};
  red.diffuse = {0.6f, 0.1f, 0.1f};
  red.specular = {1.0f, 1.0f, 1.0f};
  red.shininess = 64.0f;
  Material blue = red;
  blue.diffuse = {0.1f, 0.1f, 0.7f};
  blue.shininess = 10.0f;
  scene.materials = {red, blue};
  scene.material_names = {"red", "blue"};
  scene.objects = {sphere_object("left", {-1.2f, 0.0f, 0.0f}, 1.0f, 0),
                   sphere_object("right", {1.2f, 0.0f, 0.0f}, 1.0f, 1)};
  scene.render.width = 64;
  scene.render.height = 48;
  return scene;
}

}  // namespace gloss::test
