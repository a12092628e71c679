#pragma once
// What a scene costs in memory, estimated from its sizes before anything is allocated, for the
// budget of base/memory_budget.h (docs/spec/scene-and-cli.md, "Memory budget"). Per-triangle
// and per-pixel figures are peak resident memory of gloss-cli render, measured with
// /usr/bin/time -f %M on 1 to 40 teapots at tessellation 64 and on 512x512 to 2048x2048 images
// at 1 to 64 spp with 1 and 4 lights, then rounded up; the sample cache is the engine's own count.
#include <cstddef>
#include <cstdint>

#include "scene/scene.h"

namespace gloss {

// Per triangle of geometry: the Mesh (positions, normals, indices), the acceleration structure
// and the renderer's copies; measured ~194 bytes.
constexpr std::uint64_t kBytesPerTriangle = 200;
// Per pixel and per pixel and light besides the sample cache (images, pixel factors, file
// encodings); measured ~34 and ~8.
constexpr std::uint64_t kBytesPerPixel = 40;
constexpr std::uint64_t kBytesPerPixelLight = 8;
// gloss-cli renders the sample cache in bands of rows of about this many bytes (at least 4 rows).
constexpr std::uint64_t kSampleBandBytes = std::uint64_t(256) << 20;

// Per texel of an environment map besides its decoded samples: the map (12 bytes of RGB float)
// and the engine's tables for it (its prefiltered levels, at most about the map's own size, and
// the sampling tables, 4 bytes): rounded up.
constexpr std::uint64_t kEnvironmentBytesPerTexel = 32;

// How a renderer holds its samples: gloss-cli's renderer band by band, the editor's progressive
// renderer for the whole image.
enum class SampleMemory { banded, whole_image };

// Triangles of the Utah teapot (32 bicubic patches) at a tessellation level: 32 * 2 * level^2.
std::uint64_t teapot_triangles(int level);

// Bytes of geometry for a mesh of that many triangles.
std::uint64_t geometry_bytes(std::uint64_t triangles);

// Bytes of one row of the sample cache: width * spp samples of 20 bytes plus 16 per light (at
// least one).
std::uint64_t sample_row_bytes(int width, int spp, std::size_t lights);

// The rows of one band of gloss-cli's renderer: as many as fit kSampleBandBytes, 4 to height.
int sample_band_rows(int width, int height, int spp, std::size_t lights);

// Bytes an environment map and the engine's tables for it hold (0 without one).
std::uint64_t environment_bytes(const Environment& environment);

// Bytes the scene's map textures hold, each shared texture once.
std::uint64_t texture_bytes(const Scene& scene);

// Bytes of the render for the scene's render settings and lights.
std::uint64_t render_bytes(const RenderSettings& render, std::size_t lights, SampleMemory samples);

}  // namespace gloss
