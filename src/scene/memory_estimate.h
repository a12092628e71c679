#pragma once
// What a scene costs in memory, estimated from its sizes before anything is allocated, for the
// budget of base/memory_budget.h. The figures are peak resident memory of gloss-cli render,
// measured with /usr/bin/time -f %M on 1 to 40 teapots at tessellation 64 and on 1024x1024 and
// 2048x2048 images at 1 and 4 spp with 1 and 4 lights, then rounded up (docs/spec/
// scene-and-cli.md, "Memory budget").
#include <cstdint>

#include "scene/scene.h"

namespace gloss {

// Per triangle of geometry: the Mesh (positions, normals, indices), the acceleration structure
// and the renderer's own copies; measured ~194 bytes.
constexpr std::uint64_t kBytesPerTriangle = 200;
// Per pixel, per sample and per sample and light of the render's caches; measured ~32, ~15, ~23.
constexpr std::uint64_t kBytesPerPixel = 40;
constexpr std::uint64_t kBytesPerSample = 16;
constexpr std::uint64_t kBytesPerSampleLight = 24;

// Triangles of the Utah teapot (32 bicubic patches) at a tessellation level: 32 * 2 * level^2.
std::uint64_t teapot_triangles(int level);

// Bytes of geometry for a mesh of that many triangles.
std::uint64_t geometry_bytes(std::uint64_t triangles);

// Bytes of the render caches for the scene's render settings and lights.
std::uint64_t render_bytes(const RenderSettings& render, std::size_t lights);

}  // namespace gloss
