#include "scene/memory/scene_bytes.h"

#include <algorithm>
#include <string>
#include <vector>

namespace gloss {

namespace {

// A std::string's heap buffer, 0 while its text fits the in-place buffer (capacity 15 in
// libstdc++; the in-place capacity is that of an empty string).
std::uint64_t string_heap_bytes(const std::string& s) {
  const std::size_t in_place = std::string().capacity();
  return s.capacity() > in_place ? s.capacity() + 1 : 0;
}

template <class T>
std::uint64_t vector_bytes(const std::vector<T>& v) {
  return static_cast<std::uint64_t>(v.capacity()) * sizeof(T);
}

}  // namespace

std::uint64_t mesh_bytes(const Mesh& mesh) {
  return sizeof(Mesh) + vector_bytes(mesh.positions) + vector_bytes(mesh.normals) +
         vector_bytes(mesh.triangles) + vector_bytes(mesh.uv[0]) + vector_bytes(mesh.uv[1]) +
         vector_bytes(mesh.tangents);
}

std::uint64_t scene_bytes_without_meshes(const Scene& scene) {
  std::uint64_t total = sizeof(Scene) + string_heap_bytes(scene.path);
  total += vector_bytes(scene.lights) + vector_bytes(scene.materials) +
           vector_bytes(scene.material_names) + vector_bytes(scene.objects);
  for (const Material& m : scene.materials) total += string_heap_bytes(m.preset);
  for (const std::string& name : scene.material_names) total += string_heap_bytes(name);
  for (const Object& o : scene.objects) {
    total += string_heap_bytes(o.name) + string_heap_bytes(o.params.file) +
             string_heap_bytes(o.params.group);
  }
  return total;
}

std::uint64_t unshared_mesh_bytes(const Scene& held, const Scene& other) {
  std::vector<const Mesh*> mine, others;
  // A transformed object holds its own triangles (shape) and the placed copy (mesh).
  for (const Object& o : held.objects) {
    if (o.mesh != nullptr) mine.push_back(o.mesh.get());
    if (o.shape != nullptr) mine.push_back(o.shape.get());
  }
  for (const Object& o : other.objects) {
    others.push_back(o.mesh.get());
    others.push_back(o.shape.get());
  }
  std::sort(mine.begin(), mine.end());
  mine.erase(std::unique(mine.begin(), mine.end()), mine.end());
  std::sort(others.begin(), others.end());
  std::uint64_t total = 0;
  for (const Mesh* m : mine) {
    if (!std::binary_search(others.begin(), others.end(), m)) total += mesh_bytes(*m);
  }
  return total;
}

}  // namespace gloss
