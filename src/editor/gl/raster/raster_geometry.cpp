#include "editor/gl/raster/raster_geometry.h"

#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

#include "shading/texturing.h"
#include "texture/footprint.h"

namespace gloss {

namespace {

// Per corner: position, shading normal, the triangle's geometric normal (9 floats), then the
// shadow terminator's heights and weights (6; shaders/raster_mesh.vert). Corners are not shared:
// each carries its triangle's n_g, which the two-sided rule and the shadow bias need, and GL has
// no per-primitive attribute. A mesh with (u, v) also carries, per corner, the maps' attributes
// of shaders/raster_mesh.vert: (u, v) of sets 0 and 1, the tangent and its handedness, and its
// triangle's dp/du and dp/dv with the densities, corner positions and corners' (u, v) of both
// sets (37 floats more): the fragment shader finds the hit's barycentrics from its pixel's ray,
// as the ray tracer does, rather than from the rasterizer's interpolation.
constexpr int kFloatsPerVertex = 15;
constexpr int kFloatsPerTexturedVertex = 52;

// Corner j's terminator attributes: dot(P_j - P_k, n_k) for each corner k (in double, rounded
// once) and dot(n_j, n_g) in slot j (the barycentric weight one-hot). Zeros on flat triangles.
void append_terminator_attributes(const Mesh& mesh, const glm::uvec3& tri, const glm::vec3& face,
                                  int j, std::vector<float>& out) {
  float heights[3] = {0.0f, 0.0f, 0.0f}, weights[3] = {0.0f, 0.0f, 0.0f};
  if (mesh.smooth()) {
    const glm::dvec3 corner(mesh.positions[tri[j]]);
    for (int k = 0; k < 3; ++k) {
      const glm::dvec3 n(mesh.normals[tri[k]]);
      heights[k] = static_cast<float>(glm::dot(corner - glm::dvec3(mesh.positions[tri[k]]), n));
    }
    weights[j] = glm::dot(mesh.normals[tri[j]], face);
  }
  out.insert(out.end(), heights, heights + 3);
  out.insert(out.end(), weights, weights + 3);
}

// The corner floats the maps add (shading/map_frame.h computes the same per hit).
void append_map_attributes(const Mesh& mesh, const glm::uvec3& tri, int k,
                           std::vector<float>& out) {
  const glm::vec3 p[3] = {mesh.positions[tri.x], mesh.positions[tri.y], mesh.positions[tri.z]};
  float density[2];
  glm::vec3 dpdu(0.0f), dpdv(0.0f);
  for (int set = 0; set < 2; ++set) {
    const std::vector<glm::vec2>& uv = mesh.uv_set(set);
    density[set] = triangle_uv_density(p[0], p[1], p[2], uv[tri.x], uv[tri.y], uv[tri.z]);
    if (set == 0)
      triangle_uv_derivatives(p[0], p[1], p[2], uv[tri.x], uv[tri.y], uv[tri.z], dpdu, dpdv);
  }
  const glm::vec2 uv0 = mesh.uv_set(0)[tri[k]], uv1 = mesh.uv_set(1)[tri[k]];
  glm::vec4 tangent(dpdu, 1.0f);
  if (mesh.tangents.size() == mesh.positions.size()) tangent = mesh.tangents[tri[k]];
  // The handedness of the triangle's first corner for all three, as the ray tracer takes it.
  if (mesh.tangents.size() == mesh.positions.size()) tangent.w = mesh.tangents[tri.x].w;
  const float corner[16] = {uv0.x,     uv0.y,     uv1.x,  uv1.y,     tangent.x, tangent.y,
                            tangent.z, tangent.w, dpdu.x, dpdu.y,    dpdu.z,    density[0],
                            dpdv.x,    dpdv.y,    dpdv.z, density[1]};
  out.insert(out.end(), corner, corner + 16);
  for (const glm::vec3& q : p) out.insert(out.end(), {q.x, q.y, q.z});
  const std::vector<glm::vec2>&set0 = mesh.uv_set(0), &set1 = mesh.uv_set(1);
  out.insert(out.end(), {set0[tri.x].x, set0[tri.x].y, set0[tri.y].x, set0[tri.y].y, set0[tri.z].x,
                         set0[tri.z].y, set1[tri.x].x, set1[tri.x].y, set1[tri.y].x, set1[tri.y].y,
                         set1[tri.z].x, set1[tri.z].y});
}

MeshBuffer upload(const Mesh& mesh) {
  const bool textured = mesh.textured();
  const int floats = textured ? kFloatsPerTexturedVertex : kFloatsPerVertex;
  std::vector<float> data;
  data.reserve(mesh.triangles.size() * 3 * floats);
  for (const glm::uvec3& tri : mesh.triangles) {
    const glm::vec3 p[3] = {mesh.positions[tri.x], mesh.positions[tri.y], mesh.positions[tri.z]};
    // The ray tracer's n_g (engine/trace/surface_table.cpp): cross(p1 - p0, p2 - p0), unit.
    const glm::vec3 face = glm::normalize(glm::cross(p[1] - p[0], p[2] - p[0]));
    for (int k = 0; k < 3; ++k) {
      const glm::vec3 n = mesh.smooth() ? mesh.normals[tri[k]] : face;
      const float corner[9] = {p[k].x, p[k].y, p[k].z, n.x, n.y, n.z, face.x, face.y, face.z};
      data.insert(data.end(), corner, corner + 9);
      append_terminator_attributes(mesh, tri, face, k, data);
      if (textured) append_map_attributes(mesh, tri, k, data);
    }
  }
  MeshBuffer b;
  b.floats_per_vertex = floats;
  b.vertices = static_cast<GLsizei>(mesh.triangles.size() * 3);
  glGenVertexArrays(1, &b.vertex_array);
  glBindVertexArray(b.vertex_array);
  glGenBuffers(1, &b.buffer);
  glBindBuffer(GL_ARRAY_BUFFER, b.buffer);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(float)), data.data(),
               GL_STATIC_DRAW);
  const GLsizei stride = floats * sizeof(float);
  // Locations 0..4: position, normal, face normal, terminator heights and weights (vec3 each);
  // with maps 5..15: uv0, uv1, tangent, dpdu and density 0, dpdv and density 1, p0, p1, p2, and
  // the corners' (u, v) as three vec4. 16 in all: what GL 3.3 promises (GL_MAX_VERTEX_ATTRIBS).
  const GLint sizes[16] = {3, 3, 3, 3, 3, 2, 2, 4, 4, 4, 3, 3, 3, 4, 4, 4};
  const GLuint count = textured ? 16 : 5;
  std::size_t offset = 0;
  for (GLuint a = 0; a < count; ++a) {
    glVertexAttribPointer(a, sizes[a], GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<const void*>(offset * sizeof(float)));
    glEnableVertexAttribArray(a);
    offset += static_cast<std::size_t>(sizes[a]);
  }
  glBindVertexArray(0);
  return b;
}

void release(MeshBuffer& b) {
  glDeleteBuffers(1, &b.buffer);
  glDeleteVertexArrays(1, &b.vertex_array);
}

}  // namespace

RasterGeometry::RasterGeometry() {
  // The 12 triangles of [-1, 1]^3, each wound counter-clockwise seen from outside, so that the
  // renderer can cull the far faces when the eye is outside the cube.
  static const int kFaces[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1},
                                   {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
  const auto corner = [](int c) {  // bit 0: x, bit 1: y, bit 2: z
    return glm::vec3((c & 1) ? 1.0f : -1.0f, (c & 2) ? 1.0f : -1.0f, (c & 4) ? 1.0f : -1.0f);
  };
  std::vector<float> corners;
  for (const auto& f : kFaces) {
    static const int kTriangles[2][3] = {{0, 1, 2}, {0, 2, 3}};  // the quad's two halves
    for (const auto& tri : kTriangles) {
      glm::vec3 p[3] = {corner(f[tri[0]]), corner(f[tri[1]]), corner(f[tri[2]])};
      // The face's centre points outward; turn the triangle if its normal does not.
      if (glm::dot(glm::cross(p[1] - p[0], p[2] - p[0]), p[0] + p[1] + p[2]) < 0.0f) {
        std::swap(p[1], p[2]);
      }
      for (const glm::vec3& q : p) corners.insert(corners.end(), {q.x, q.y, q.z});
    }
  }
  glGenVertexArrays(1, &m_cube_array);
  glBindVertexArray(m_cube_array);
  glGenBuffers(1, &m_cube_buffer);
  glBindBuffer(GL_ARRAY_BUFFER, m_cube_buffer);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(corners.size() * sizeof(float)),
               corners.data(), GL_STATIC_DRAW);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), nullptr);
  glEnableVertexAttribArray(0);
  glBindVertexArray(0);
}

RasterGeometry::~RasterGeometry() {
  for (auto& [key, entry] : m_meshes) release(entry.buffer);
  glDeleteBuffers(1, &m_cube_buffer);
  glDeleteVertexArrays(1, &m_cube_array);
}

int RasterGeometry::sync(const Scene& scene) {
  std::set<const Mesh*> used;
  int uploaded = 0;
  for (const Object& o : scene.objects) {
    if (o.type == ObjectType::sphere || !o.mesh) continue;
    used.insert(o.mesh.get());
    if (m_meshes.count(o.mesh.get()) != 0) continue;
    m_meshes.emplace(o.mesh.get(), Entry{o.mesh, upload(*o.mesh)});
    ++uploaded;
  }
  for (auto it = m_meshes.begin(); it != m_meshes.end();) {
    if (used.count(it->first) != 0) {
      ++it;
      continue;
    }
    release(it->second.buffer);
    it = m_meshes.erase(it);
  }
  return uploaded;
}

const MeshBuffer& RasterGeometry::mesh(const Mesh& mesh) const {
  const auto found = m_meshes.find(&mesh);
  if (found == m_meshes.end()) throw std::logic_error("raster geometry: mesh not synced");
  return found->second.buffer;
}

std::size_t RasterGeometry::bytes() const {
  std::size_t total = 36 * 3 * sizeof(float);
  for (const auto& [key, entry] : m_meshes) {
    total += static_cast<std::size_t>(entry.buffer.vertices) * entry.buffer.floats_per_vertex *
             sizeof(float);
  }
  return total;
}

}  // namespace gloss
