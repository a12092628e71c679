#include "analysis/bench/ray_baseline.h"

#include <algorithm>
#include <limits>

#include <tbb/parallel_for.h>
#include <glm/geometric.hpp>

#include "engine/parallel_loops.h"
#include "engine/simd/lane_mask.h"
#include "engine/simd/lanes.h"
#include "engine/trace/ray_packet.h"
#include "scene/camera.h"

namespace gloss {

long long trace_rays_raw(const Scene& scene, const EmbreeScene& embree, int width, int height) {
  const CameraFrame cam = make_camera_frame(scene.camera, width, height);
  std::vector<glm::vec3> lights;
  if (scene.render.shadows) {
    for (const PointLight& l : scene.lights) {
      if (l.diffuse != glm::vec3(0.0f) || l.specular != glm::vec3(0.0f))
        lights.push_back(l.position);
    }
  }
  std::atomic<long long> total{0};
  // Bands of whole rows and kLanes-pixel packets, as the renderer (sample_packet.h).
  parallel_rows(width, height, nullptr, [&](int y0, int y1) {
    const int x0 = 0, x1 = width;
    long long rays = 0;
    RTCIntersectContext context = coherent_context();
    for (int y = y0; y < y1; ++y) {
      for (int bx = x0; bx < x1; bx += kLanes) {
        RTCRayHit16 rh;
        alignas(64) int valid[kLanes];  // Embree requires 64-byte aligned masks
        for (int i = 0; i < kLanes; ++i) {
          const int x = bx + i;
          valid[i] = x < x1 ? -1 : 0;
          const glm::vec3 d = primary_direction(cam, x + 0.5f, y + 0.5f, width, height);
          set_packet_ray(rh.ray, i, cam.eye, d);
          rh.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
        }
        rays += count_set_lanes(valid);
        rtcIntersect16(valid, embree.handle(), &context, &rh);
        for (const glm::vec3& light : lights) {
          RTCRay16 sr;
          alignas(64) int svalid[kLanes];
          for (int i = 0; i < kLanes; ++i) {
            svalid[i] = valid[i] && rh.hit.geomID[i] != RTC_INVALID_GEOMETRY_ID ? -1 : 0;
            const glm::vec3 d(rh.ray.dir_x[i], rh.ray.dir_y[i], rh.ray.dir_z[i]);
            glm::vec3 ng(rh.hit.Ng_x[i], rh.hit.Ng_y[i], rh.hit.Ng_z[i]);
            if (glm::dot(ng, d) > 0.0f) ng = -ng;
            const glm::vec3 p = cam.eye + rh.ray.tfar[i] * d;
            const glm::vec3 o = svalid[i] ? p + 1e-4f * glm::normalize(ng) : glm::vec3(0.0f);
            const glm::vec3 to = light - o;
            set_packet_ray(sr, i, o, to, kShadowRayEnd);
          }
          rays += count_set_lanes(svalid);
          rtcOccluded16(svalid, embree.handle(), &context, &sr);
        }
      }
    }
    total.fetch_add(rays, std::memory_order_relaxed);
  });
  return total.load();
}

StreamingPass::StreamingPass(std::size_t read_bytes, std::size_t write_bytes)
    : m_in(std::max<std::size_t>(1, read_bytes / sizeof(float)), 1.0f),
      m_out(std::max<std::size_t>(1, write_bytes / sizeof(float)), 0.0f) {}

void StreamingPass::run() {
  // Each block of outputs gets the sum of its share of the input: one vectorised reduction over
  // the share, then the block written. (Summing each output's few inputs one after another, as
  // this did before, was a chain of dependent adds per element: slower than the re-shades it
  // was the floor of.)
  const std::size_t out_n = m_out.size(), in_n = m_in.size();
  const float* in = m_in.data();
  float* out = m_out.data();
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, out_n, 16384),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      const std::size_t from = r.begin() * in_n / out_n;
                      const std::size_t to = r.end() * in_n / out_n;
                      float sum = 0.0f;
#pragma omp simd reduction(+ : sum)
                      for (std::size_t k = from; k < to; ++k) sum += in[k];
#pragma omp simd
                      for (std::size_t i = r.begin(); i < r.end(); ++i) out[i] = sum;
                    });
}

}  // namespace gloss
