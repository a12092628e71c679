#include "editor/gl/glsl_harness.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "editor/gl/gl_program.h"
#include "reference/reference_renderer.h"
#include "scene/camera.h"

namespace gloss::test {

const char* const kGlslTermNames[kGlslTerms] = {"total", "emissive", "ambient", "diffuse",
                                                "specular"};

namespace {

// One point per covered pixel, at the pixel's centre, carrying that pixel's hit point and normal;
// the exported shader does the rest. Points of size 1 at pixel centres cover exactly their pixel.
const char* const kPointVertexShader = R"glsl(#version 330 core
layout(location = 0) in vec2 pixel_ndc;
layout(location = 1) in vec3 hit_position;
layout(location = 2) in vec3 hit_normal;
out vec3 gloss_position;
out vec3 gloss_normal;
void main() {
  gloss_position = hit_position;
  gloss_normal = hit_normal;
  gl_Position = vec4(pixel_ndc, 0.0, 1.0);
}
)glsl";

using D3 = glm::dvec3;
constexpr double kNone = std::numeric_limits<double>::infinity();

// Nearest t > 0 of the unit ray o + t d on the sphere, or kNone.
double sphere_t(const Object& s, const D3& o, const D3& d) {
  const D3 oc = o - D3(s.center);
  const double r = s.radius;
  const double b = glm::dot(oc, d), disc = b * b - (glm::dot(oc, oc) - r * r);
  if (disc < 0.0) return kNone;
  const double root = std::sqrt(disc);
  if (-b - root > 0.0) return -b - root;
  return -b + root > 0.0 ? -b + root : kNone;
}

// Moller-Trumbore in double; t and the barycentrics of corners 1 and 2, or t = kNone.
double triangle_t(const Mesh& mesh, std::size_t prim, const D3& o, const D3& d, double& u,
                  double& v) {
  const glm::uvec3 tri = mesh.triangles[prim];
  const D3 p0(mesh.positions[tri.x]), e1 = D3(mesh.positions[tri.y]) - p0,
                                      e2 = D3(mesh.positions[tri.z]) - p0;
  const D3 pvec = glm::cross(d, e2);
  const double det = glm::dot(e1, pvec);
  if (det == 0.0) return kNone;
  const D3 s = o - p0, qvec = glm::cross(s, e1);
  u = glm::dot(s, pvec) / det;
  v = glm::dot(d, qvec) / det;
  if (u < 0.0 || v < 0.0 || u + v > 1.0) return kNone;
  const double t = glm::dot(e2, qvec) / det;
  return t > 0.0 ? t : kNone;
}

}  // namespace

GLuint compile_shader(GLenum type, const std::string& source, std::string& log) {
  try {
    return gloss::compile_shader(type, source, "an exported shader");
  } catch (const std::runtime_error& e) {
    log += e.what();
    return 0;
  }
}

std::vector<std::vector<float>> host_hits(const Scene& scene) {
  const int w = scene.render.width, h = scene.render.height;
  const CameraBasis<double> basis = make_camera_basis<double>(scene.camera, w, h);
  std::vector<std::vector<float>> hits(scene.objects.size());
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const D3 d = camera_direction<double>(basis, x + 0.5, y + 0.5, w, h);
      double best = kNone;
      std::size_t object = 0, prim = 0;
      double bu = 0.0, bv = 0.0;
      for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const Object& o = scene.objects[i];
        if (o.type == ObjectType::sphere) {
          const double t = sphere_t(o, basis.eye, d);
          if (t < best) best = t, object = i;
          continue;
        }
        for (std::size_t k = 0; k < o.mesh->triangles.size(); ++k) {
          double u = 0.0, v = 0.0;
          const double t = triangle_t(*o.mesh, k, basis.eye, d, u, v);
          if (t < best) best = t, object = i, prim = k, bu = u, bv = v;
        }
      }
      if (best == kNone) continue;
      const Object& o = scene.objects[object];
      const D3 p = basis.eye + best * d;
      D3 n;
      if (o.type == ObjectType::sphere) {
        n = (p - D3(o.center)) / double(o.radius);
      } else {
        const Mesh& mesh = *o.mesh;
        const glm::uvec3 tri = mesh.triangles[prim];
        if (mesh.smooth()) {
          n = glm::normalize((1.0 - bu - bv) * D3(mesh.normals[tri.x]) +
                             bu * D3(mesh.normals[tri.y]) + bv * D3(mesh.normals[tri.z]));
        } else {
          const D3 p0(mesh.positions[tri.x]);
          n = glm::normalize(
              glm::cross(D3(mesh.positions[tri.y]) - p0, D3(mesh.positions[tri.z]) - p0));
        }
      }
      const float row[8] = {float(2.0 * (x + 0.5) / w - 1.0),
                            float(1.0 - 2.0 * (y + 0.5) / h),
                            float(p.x),
                            float(p.y),
                            float(p.z),
                            float(n.x),
                            float(n.y),
                            float(n.z)};
      hits[object].insert(hits[object].end(), row, row + 8);
    }
  }
  return hits;
}

namespace {

std::vector<std::vector<float>> render_hits(const Scene& scene,
                                            const std::vector<std::vector<float>>& hits,
                                            const std::function<std::string(int)>& fragment,
                                            std::string& log,
                                            const std::function<void(GLuint)>& setup = {}) {
  const int w = scene.render.width, h = scene.render.height;

  // One program per material in use.
  std::map<int, GLuint> programs;
  bool built = true;
  for (const Object& o : scene.objects) {
    if (programs.count(o.material) != 0) continue;
    GLuint program = 0;
    try {
      program = build_program(kPointVertexShader, fragment(o.material), "an exported shader");
    } catch (const std::runtime_error& e) {
      log += e.what();
      built = false;
    }
    programs[o.material] = program;
  }
  if (!built) {
    for (const auto& [material, program] : programs) glDeleteProgram(program);
    return {};
  }

  GLuint framebuffer = 0, textures[kGlslTerms] = {};
  glGenFramebuffers(1, &framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glGenTextures(kGlslTerms, textures);
  GLenum buffers[kGlslTerms];
  for (int i = 0; i < kGlslTerms; ++i) {
    glBindTexture(GL_TEXTURE_2D, textures[i]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, w, h, 0, GL_RGBA, GL_FLOAT, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    buffers[i] = GL_COLOR_ATTACHMENT0 + i;
    glFramebufferTexture2D(GL_FRAMEBUFFER, buffers[i], GL_TEXTURE_2D, textures[i], 0);
  }
  glDrawBuffers(kGlslTerms, buffers);
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), static_cast<GLenum>(GL_FRAMEBUFFER_COMPLETE));
  glViewport(0, 0, w, h);
  // A miss: background in the total, 0 in every term (spec, first section).
  const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  const float background[4] = {scene.background.x, scene.background.y, scene.background.z, 0.0f};
  glClearBufferfv(GL_COLOR, 0, background);
  for (int i = 1; i < kGlslTerms; ++i) glClearBufferfv(GL_COLOR, i, zero);

  GLuint vao = 0, vbo = 0;
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glGenBuffers(1, &vbo);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  const GLsizei stride = 8 * sizeof(float);
  const glm::vec3 eye = scene.camera.eye;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    if (hits[i].empty()) continue;
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(hits[i].size() * sizeof(float)),
                 hits[i].data(), GL_STREAM_DRAW);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, stride, nullptr);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<const void*>(2 * sizeof(float)));
    glVertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<const void*>(5 * sizeof(float)));
    for (GLuint a = 0; a < 3; ++a) glEnableVertexAttribArray(a);
    const GLuint program = programs.at(scene.objects[i].material);
    glUseProgram(program);
    glUniform3f(glGetUniformLocation(program, "gloss_eye"), eye.x, eye.y, eye.z);
    if (setup) setup(program);
    glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(hits[i].size() / 8));
  }

  std::vector<std::vector<float>> images(kGlslTerms);
  std::vector<float> bottom_up(static_cast<std::size_t>(w) * h * 4);
  const std::size_t row = static_cast<std::size_t>(w) * 4;
  for (int i = 0; i < kGlslTerms; ++i) {
    glReadBuffer(GL_COLOR_ATTACHMENT0 + i);
    glReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, bottom_up.data());
    images[i].resize(bottom_up.size());
    for (int y = 0; y < h; ++y) {
      std::copy_n(&bottom_up[(h - 1 - y) * row], row, &images[i][y * row]);
    }
  }
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  glUseProgram(0);
  glDeleteBuffers(1, &vbo);
  glDeleteVertexArrays(1, &vao);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteTextures(kGlslTerms, textures);
  glDeleteFramebuffers(1, &framebuffer);
  for (const auto& [material, program] : programs) glDeleteProgram(program);
  return images;
}

}  // namespace

std::vector<std::vector<float>> render_exported(const Scene& scene,
                                                const std::function<std::string(int)>& fragment,
                                                std::string& log,
                                                const std::function<void(GLuint)>& setup) {
  return render_hits(scene, host_hits(scene), fragment, log, setup);
}

Agreement compare_with_reference(const Scene& scene,
                                 const std::function<glm::vec3(int, std::size_t)>& at,
                                 double tolerance, ReferenceOptions options,
                                 std::vector<std::uint8_t>* edges_out) {
  Agreement a;
  options.spp = 1;
  std::vector<std::uint8_t> edges;
  options.edges = &edges;
  const TermImages ref = render_reference<double>(scene, options);
  const Image* images[kGlslTerms] = {&ref.total, &ref.emissive, &ref.ambient, &ref.diffuse,
                                     &ref.specular};
  for (int t = 0; t < kGlslTerms; ++t) {
    std::size_t good = 0;
    for (std::size_t i = 0; i < images[t]->pixels.size(); ++i) {
      const glm::vec3 r = images[t]->pixels[i];
      const glm::vec3 g = at(t, i);
      double e = 0.0;
      for (int k = 0; k < 3; ++k) {
        // A NaN or Inf from the shader counts as the largest possible difference (std::max
        // would drop a NaN).
        e = std::max(e, std::isfinite(g[k]) ? std::abs(double(g[k]) - double(r[k])) : kNone);
      }
      a.largest[t] = std::max(a.largest[t], e);
      if (e <= tolerance) {
        ++good;
      } else if (edges[i] == 0) {
        ++a.off_edge[t];
      }
    }
    a.share[t] = double(good) / double(images[t]->pixels.size());
  }
  if (edges_out != nullptr) *edges_out = std::move(edges);
  return a;
}

Agreement measure_agreement(const Scene& scene, const std::function<std::string(int)>& fragment,
                            double tolerance, std::string& log) {
  const std::vector<std::vector<float>> hits = host_hits(scene);
  const std::vector<std::vector<float>> gl = render_hits(scene, hits, fragment, log);
  if (gl.empty()) return {};
  Agreement a = compare_with_reference(
      scene,
      [&](int t, std::size_t i) {
        return glm::vec3(gl[t][4 * i], gl[t][4 * i + 1], gl[t][4 * i + 2]);
      },
      tolerance);
  for (const std::vector<float>& object_hits : hits) {
    a.covered += static_cast<int>(object_hits.size() / 8);
  }
  return a;
}

}  // namespace gloss::test
