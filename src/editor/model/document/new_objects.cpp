#include "editor/model/document/new_objects.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <memory>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "base/error.h"
#include "editor/model/document/command.h"
#include "editor/model/view/camera_controller.h"
#include "engine/pick.h"
#include "io/model/model_loader.h"
#include "io/model/model_maps.h"
#include "io/scene/scene_files.h"
#include "io/scene/scene_loader.h"
#include "scene/geometry/placement.h"
#include "scene/geometry/shapes.h"

namespace gloss {

namespace {

constexpr int kRings = 16;  // candidate grid: (2 kRings + 1)^2 places a quarter footprint apart
constexpr float kTeapotWidth = 6.43f;  // the teapot's largest side at scale 1 (spout to handle)
constexpr const char* kDefaultMaterial = "default";  // the loader's grey for parts without one

struct Box {
  glm::vec3 lo, hi;
  int object = -1;
};

std::vector<Box> visible_boxes(const Scene& scene) {
  std::vector<Box> boxes;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    Box b;
    b.object = static_cast<int>(i);
    if (!scene.objects[i].hidden && object_bounds(scene.objects[i], b.lo, b.hi)) {
      boxes.push_back(b);
    }
  }
  return boxes;
}

float largest_side(const glm::vec3& lo, const glm::vec3& hi) {
  const glm::vec3 e = hi - lo;
  return std::max(e.x, std::max(e.y, e.z));
}

// Strictly overlapping boxes: touching faces (an object resting on another) do not count.
bool overlap(const Box& a, const Box& b, float slack) {
  for (int k = 0; k < 3; ++k) {
    if (!(a.lo[k] < b.hi[k] - slack && b.lo[k] < a.hi[k] - slack)) return false;
  }
  return true;
}

// Whether the segment from p to q passes through the box [lo, hi] (slab test).
bool segment_meets_box(const glm::vec3& p, const glm::vec3& q, const glm::vec3& lo,
                       const glm::vec3& hi) {
  float t0 = 0.0f, t1 = 1.0f;
  const glm::vec3 d = q - p;
  for (int k = 0; k < 3; ++k) {
    if (d[k] == 0.0f) {
      if (p[k] < lo[k] || p[k] > hi[k]) return false;
      continue;
    }
    float a = (lo[k] - p[k]) / d[k], b = (hi[k] - p[k]) / d[k];
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
    if (t0 > t1) return false;
  }
  return true;
}

// The unique names of a new object and of its new material.
void name_new(const Scene& scene, AddObjects& add, const std::string& base) {
  Object& o = add.objects.back();
  o.name = unique_object_name(scene, base);
  add.material_names.push_back(unique_material_name(scene, o.name));
  add.materials.push_back(Material{});
  o.material = static_cast<int>(scene.materials.size());
}

}  // namespace

float new_object_size(const Scene& scene) {
  const std::vector<Box> boxes = visible_boxes(scene);
  if (boxes.empty()) return 2.0f;
  glm::vec3 lo = boxes[0].lo, hi = boxes[0].hi;
  std::vector<float> solid;
  for (const Box& b : boxes) {
    lo = glm::min(lo, b.lo);
    hi = glm::max(hi, b.hi);
    const glm::vec3 e = b.hi - b.lo;
    const float side = largest_side(b.lo, b.hi);
    if (side > 0.0f && std::min(e.x, std::min(e.y, e.z)) > 0.05f * side) solid.push_back(side);
  }
  const float scene_side = std::max(largest_side(lo, hi), 1e-3f);
  if (solid.empty()) return 0.3f * scene_side;
  std::sort(solid.begin(), solid.end());
  return std::min(solid[solid.size() / 2], 0.35f * scene_side);
}

glm::vec3 placement_offset(const Scene& scene, const glm::vec3& lo, const glm::vec3& hi) {
  const glm::vec3 size = hi - lo;
  const glm::vec3 centre = 0.5f * (lo + hi);
  const glm::vec3 target = scene.camera.target;
  const std::vector<Box> boxes = visible_boxes(scene);
  if (boxes.empty()) return target - centre;
  glm::vec3 scene_lo = boxes[0].lo;
  for (const Box& b : boxes) scene_lo = glm::min(scene_lo, b.lo);

  // Candidate centres (x, z) on a grid a quarter of the footprint apart (fine enough to find a
  // gap the object fits, a room's corner beside a block), nearest first, where distances along
  // the view count three times: beside the objects as the camera sees them, rather than in front of
  // them (hiding them) or behind them (hidden).
  const float side = std::max(largest_side(lo, hi), 1e-3f);
  const float step = 0.25f * std::max(std::max(size.x, size.z), 0.25f * side);
  glm::vec2 view(target.x - scene.camera.eye.x, target.z - scene.camera.eye.z);
  view = glm::length(view) > 0.0f ? glm::normalize(view) : glm::vec2(0.0f, -1.0f);
  const auto cost = [&](const glm::vec2& g) {
    const float along = glm::dot(g, view);
    return glm::dot(g, g) + 8.0f * along * along;  // (3 along)^2 + across^2
  };
  std::vector<glm::vec2> places;
  for (int i = -kRings; i <= kRings; ++i) {
    for (int j = -kRings; j <= kRings; ++j) places.emplace_back(i, j);
  }
  std::stable_sort(places.begin(), places.end(),
                   [&](const glm::vec2& a, const glm::vec2& b) { return cost(a) < cost(b); });
  // Five rays per candidate from above where it would rest, cast in one Embree build.
  const float from_y = std::max(target.y, scene_lo.y) + size.y + 1e-3f * side;
  const glm::vec2 corner(0.45f * size.x, 0.45f * size.z);
  const glm::vec2 offsets[5] = {{0, 0}, {-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  std::vector<glm::vec3> points;
  for (glm::vec2& p : places) {
    p = glm::vec2(target.x, target.z) + p * step;
    for (const glm::vec2& o : offsets) {
      points.emplace_back(p.x + o.x * corner.x, from_y, p.y + o.y * corner.y);
    }
  }
  const std::vector<SurfaceBelow> below = surfaces_below(scene, points);

  // Each candidate's support and whether it is a free place; the free places on the lowest
  // support (the ground) come first, so a new object stands beside a box, not on it; among
  // them the ones the camera sees.
  const float slack = 1e-3f * side;
  std::vector<glm::vec3> offsets_of(places.size()), centres(places.size());
  std::vector<bool> free(places.size(), false), supported(places.size(), false);
  float ground = std::numeric_limits<float>::infinity();
  for (std::size_t c = 0; c < places.size(); ++c) {
    float support = -std::numeric_limits<float>::infinity();
    std::vector<int> supports;
    bool narrow = false;
    for (std::size_t k = 0; k < 5; ++k) {
      const SurfaceBelow& hit = below[5 * c + k];
      if (hit.object < 0) continue;
      glm::vec3 a, b;
      object_bounds(scene.objects[static_cast<std::size_t>(hit.object)], a, b);
      // A surface to stand on is the top of what it belongs to (a floor, a table top; not the
      // shoulder of a sphere) and at least as wide as the footprint.
      if (b.y > hit.y + slack || b.x - a.x < size.x || b.z - a.z < size.z) narrow = true;
      support = std::max(support, hit.y);
      supports.push_back(hit.object);
    }
    if (supports.empty()) support = scene_lo.y;
    supported[c] = !supports.empty();
    offsets_of[c] = glm::vec3(places[c].x - centre.x, support - lo.y, places[c].y - centre.z);
    centres[c] = centre + offsets_of[c];
    if (narrow) continue;
    // Clear of the others by a tenth of its size, so that it stands beside them, not against them.
    const glm::vec3 gap(0.1f * side);
    const Box placed{lo + offsets_of[c] - gap, hi + offsets_of[c] + gap};
    free[c] = std::none_of(boxes.begin(), boxes.end(), [&](const Box& b) {
      return std::find(supports.begin(), supports.end(), b.object) == supports.end() &&
             overlap(placed, b, slack);
    });
    if (!supports.empty()) ground = std::min(ground, support);
  }
  // Seen: its centre and three of four points of its upper part reach the eye (not behind the
  // others), and it hides the centre of no solid object (not in front of them).
  std::vector<glm::vec3> probes;
  for (const glm::vec3& c : centres) {
    probes.push_back(c);
    for (std::size_t k = 1; k < 5; ++k) {
      probes.push_back(
          c + glm::vec3(0.3f * offsets[k].x * size.x, 0.3f * size.y, 0.3f * offsets[k].y * size.z));
    }
  }
  const std::vector<bool> unhidden = seen_from_eye(scene, probes);
  const auto seen = [&](std::size_t c) {
    const auto first = unhidden.begin() + static_cast<std::ptrdiff_t>(5 * c);
    return *first && std::count(first + 1, first + 5, true) >= 3;
  };
  const auto hides = [&](std::size_t c) {
    const glm::vec3 a = lo + offsets_of[c], b = hi + offsets_of[c];
    return std::any_of(boxes.begin(), boxes.end(), [&](const Box& o) {
      const glm::vec3 e = o.hi - o.lo;
      if (std::min(e.x, std::min(e.y, e.z)) <= 0.05f * largest_side(o.lo, o.hi)) return false;
      return segment_meets_box(scene.camera.eye, 0.5f * (o.lo + o.hi), a, b);
    });
  };
  const int w = std::max(scene.render.width, 1), h = std::max(scene.render.height, 1);
  const auto in_view = [&](std::size_t c) {
    glm::vec2 at;
    return project_point(scene.camera, w, h, centres[c], at) && at.x > 0.1f * w &&
           at.x < 0.9f * w && at.y > 0.1f * h && at.y < 0.9f * h && seen(c) && !hides(c);
  };
  const auto on_ground = [&](std::size_t c) {
    return supported[c] && offsets_of[c].y + lo.y <= ground + slack;
  };
  // Seen on the ground, then on the ground, then on any surface, then anywhere free (beside
  // the scene, on the level of its lowest point).
  const std::function<bool(std::size_t)> tiers[4] = {
      [&](std::size_t c) { return on_ground(c) && in_view(c); }, on_ground,
      [&](std::size_t c) { return bool(supported[c]); }, [](std::size_t) { return true; }};
  for (const auto& tier : tiers) {
    for (std::size_t c = 0; c < places.size(); ++c) {
      if (free[c] && tier(c)) return offsets_of[c];
    }
  }
  return offsets_of[0];
}

AddObjects primitive_objects(const Scene& scene, ObjectType type) {
  const float size = new_object_size(scene);
  const float h = 0.5f * size;
  AddObjects add;
  add.objects.emplace_back();
  Object& o = add.objects.back();
  o.type = type;
  ShapeParams& p = o.params;
  switch (type) {
    case ObjectType::sphere: {
      const glm::vec3 offset = placement_offset(scene, glm::vec3(-h), glm::vec3(h));
      p.center = offset;
      p.radius = h;
      break;
    }
    case ObjectType::quad: {
      // Upright, facing the camera across the ground: normal = the view direction turned
      // horizontal and back towards the eye.
      glm::vec3 facing = scene.camera.eye - scene.camera.target;
      facing.y = 0.0f;
      facing = glm::length(facing) > 0.0f ? glm::normalize(facing) : glm::vec3(0, 0, 1);
      const glm::vec3 right = glm::cross(glm::vec3(0, 1, 0), facing);
      const glm::vec3 up(0, 1, 0);
      const glm::vec3 corners[4] = {-right * h - up * h, right * h - up * h, right * h + up * h,
                                    -right * h + up * h};
      glm::vec3 lo = corners[0], hi = corners[0];
      for (const glm::vec3& c : corners) {
        lo = glm::min(lo, c);
        hi = glm::max(hi, c);
      }
      const glm::vec3 offset = placement_offset(scene, lo, hi);
      for (int i = 0; i < 4; ++i) p.quad[i] = corners[i] + offset;
      o.shape = std::make_shared<const Mesh>(make_quad(p.quad[0], p.quad[1], p.quad[2], p.quad[3]));
      break;
    }
    case ObjectType::box: {
      p.box_min = glm::vec3(-h);
      p.box_max = glm::vec3(h);
      p.position = placement_offset(scene, p.box_min, p.box_max);
      Mesh mesh = make_box(p.box_min, p.box_max);
      transform_mesh(mesh,
                     glm::translate(glm::mat4(1.0f), p.position));  // the reader's, rotate_y 0
      o.shape = std::make_shared<const Mesh>(std::move(mesh));
      break;
    }
    case ObjectType::teapot: {
      p.scale = glm::vec3(size / kTeapotWidth);
      Mesh mesh = teapot_mesh(p);  // at the origin, to find its bounds
      glm::vec3 lo, hi;
      mesh_bounds(mesh, lo, hi);
      p.position = placement_offset(scene, lo, hi);
      o.shape = std::make_shared<const Mesh>(teapot_mesh(p));
      break;
    }
    case ObjectType::mesh:
      throw CommandError("a mesh comes from a model file: object add model PATH");
  }
  name_new(scene, add, to_string(type));
  place_object(o);
  add.label = std::string("add ") + to_string(type);
  return add;
}

AddObjects model_objects(const Scene& scene, const std::string& path,
                         std::vector<std::string>* warnings, std::vector<std::string>* notes) {
  Model model = load_model(path);
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (const ModelPart& part : model.parts) {
    glm::vec3 a, b;
    if (!mesh_bounds(part.mesh, a, b)) continue;
    lo = glm::min(lo, a);
    hi = glm::max(hi, b);
  }
  if (!(lo.x <= hi.x)) throw InputError(path, "the model has no vertices");
  const float side = largest_side(lo, hi);
  const float scale = side > 0.0f ? new_object_size(scene) / side : 1.0f;
  // The model's own placement (the mesh object's scale and position): scaled about the file's
  // origin, then moved to its place; the transform stays the identity.
  const glm::vec3 position = placement_offset(scene, lo * scale, hi * scale);
  const glm::mat4 own = glm::scale(glm::translate(glm::mat4(1.0f), position), glm::vec3(scale));
  // The model file and its maps named as the scene names files, both the same way (a map made
  // from the model, MODEL#MATERIAL/SLOT, finds the model the object names in the loader's cache).
  const std::string model_name = name_for_scene(path, scene.path);
  name_maps_for_scene(model.materials, model_name);
  const std::string stem = std::filesystem::path(path).stem().string();

  AddObjects add;
  Scene named = scene;  // names taken so far, for unique ones
  int default_material = find_material(scene, kDefaultMaterial);
  for (const ModelPart& part : model.parts) {
    Object o;
    o.type = ObjectType::mesh;
    o.name = unique_object_name(named, model.parts.size() > 1 && !part.material_name.empty()
                                           ? stem + "/" + part.material_name
                                           : stem);
    o.params.file = model_name;
    o.params.group = part.material_name;
    o.params.position = position;
    o.params.scale = glm::vec3(scale);
    if (part.material_name.empty()) {
      if (default_material < 0) {  // the grey of the material defaults, shared
        default_material = static_cast<int>(named.materials.size());
        named.material_names.push_back(kDefaultMaterial);
        named.materials.push_back(Material{});
        add.material_names.push_back(kDefaultMaterial);
        add.materials.push_back(Material{});
      }
      o.material = default_material;
    } else {
      Material material;
      for (std::size_t i = 0; i < model.material_names.size(); ++i) {
        if (model.material_names[i] == part.material_name) material = model.materials[i];
      }
      const std::string name = unique_material_name(named, stem + "/" + part.material_name);
      o.material = static_cast<int>(named.materials.size());
      named.material_names.push_back(name);
      named.materials.push_back(material);
      add.material_names.push_back(name);
      add.materials.push_back(material);
    }
    Mesh mesh = part.mesh;
    transform_mesh(mesh, own);
    o.shape = std::make_shared<const Mesh>(std::move(mesh));
    place_object(o);
    named.objects.push_back(o);
    add.objects.push_back(std::move(o));
  }
  if (warnings != nullptr)
    warnings->insert(warnings->end(), model.warnings.begin(), model.warnings.end());
  if (notes != nullptr) notes->insert(notes->end(), model.notes.begin(), model.notes.end());
  add.label = "add " + std::filesystem::path(path).filename().string();
  return add;
}

}  // namespace gloss
