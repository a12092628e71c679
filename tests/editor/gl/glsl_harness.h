#pragma once
// A host program for exported GLSL shaders (editor/model/export/glsl_export.h) in the EGL tests:
// the CPU finds each pixel's primary hit exactly, in double (docs/spec/shading.md's camera formula
// at the pixel centre, the nearest sphere or triangle), and hands its point and normal to the
// exported shader as one GL point at that pixel's centre; the five outputs are read back as
// floats. Shadows are not modelled (the export has none): compare with shadows off.
#include <functional>
#include <string>
#include <vector>

#include <glad/gl.h>

#include "base/image.h"
#include "reference/reference_renderer.h"
#include "scene/scene.h"

namespace gloss::test {

constexpr int kGlslTerms = 5;  // total, emissive, ambient, diffuse, specular (the export's order)
extern const char* const kGlslTermNames[kGlslTerms];

// Compiles one shader; appends the info log to log when it fails.
GLuint compile_shader(GLenum type, const std::string& source, std::string& log);

// Per object of scene, the pixels whose nearest primary hit is on it: 8 floats each (pixel
// centre in NDC xy, hit point xyz, normal xyz). Spheres: the exact normal. Smooth meshes: the
// vertex normals interpolated; flat meshes: the triangle's normal as wound (unflipped: the
// shader applies the two-sided rule). Brute force over every triangle, fine for test scenes.
std::vector<std::vector<float>> host_hits(const Scene& scene);

// Draws each object's hits with the program made of fragment(material of the object); returns
// the five images as RGBA floats, rows top to bottom, misses at the background (total) and 0.
// Empty, with the compiler's messages in log, when a program does not build.
// setup(program), when given, runs with each program in use before it draws (samplers).
std::vector<std::vector<float>> render_exported(const Scene& scene,
                                                const std::function<std::string(int)>& fragment,
                                                std::string& log,
                                                const std::function<void(GLuint)>& setup = {});

// How the five GL images agree with render_reference<double>(scene) at 1 spp.
struct Agreement {
  double share[kGlslTerms] = {};    // pixels within tolerance, total first
  double largest[kGlslTerms] = {};  // largest channel difference
  int covered = 0;                  // pixels the host found a hit for
  // Pixels beyond tolerance that are not on the reference's silhouette / edge mask
  // (ReferenceOptions::edges: where a hit can flip between two evaluations), total first.
  int off_edge[kGlslTerms] = {};
};
Agreement measure_agreement(const Scene& scene, const std::function<std::string(int)>& fragment,
                            double tolerance, std::string& log);

// How five GL images (total, emissive, ambient, diffuse, specular: kGlslTermNames' order; one
// RGB triple per pixel, read through at(term, pixel)) agree with render_reference<double>(scene,
// options) (options.spp is forced to 1 and options.edges to a mask of its own). edges_out, when
// given, receives that mask.
Agreement compare_with_reference(const Scene& scene,
                                 const std::function<glm::vec3(int, std::size_t)>& at,
                                 double tolerance, ReferenceOptions options = {},
                                 std::vector<std::uint8_t>* edges_out = nullptr);

}  // namespace gloss::test
