#include "reference/pixel_inspection.h"

#include <stdexcept>
#include <string>

#include "engine/trace/embree_scene.h"
#include "reference/reference_sample.h"
#include "scene/fields/validation.h"

namespace gloss {

using namespace reference_detail;

// The pixel inspector: one sample (the pixel centre) through shade_sample in double, recording.
struct PixelInspector::State {
  Scene scene;
  EmbreeScene embree;
  ReferenceEnvironment environment;
  explicit State(const Scene& s) : scene(s), embree(scene), environment(scene, bounded()) {}
  static ReferenceEnvironmentOptions bounded() {
    ReferenceEnvironmentOptions o;
    o.bounded = true;  // the inspector shows every integral with its bound
    return o;
  }
};

PixelInspector::PixelInspector(const Scene& scene) {
  validate_scene(scene);
  m = std::make_unique<State>(scene);
}

PixelInspector::~PixelInspector() = default;

PixelBreakdown PixelInspector::inspect(int x, int y) const {
  const Scene& scene = m->scene;
  if (x < 0 || y < 0 || x >= scene.render.width || y >= scene.render.height) {
    throw std::out_of_range("pixel " + std::to_string(x) + " " + std::to_string(y) +
                            " is outside the " + std::to_string(scene.render.width) + "x" +
                            std::to_string(scene.render.height) + " render");
  }
  Job<double> job = make_job<double>(scene, m->embree.handle(), 1, PowMode::exact);
  job.environment = &m->environment;
  PixelBreakdown out;
  out.x = x;
  out.y = y;
  out.width = job.width;
  out.height = job.height;
  out.model = scene.render.model;
  PixelSums<double> sum;
  SampleKey key;
  shade_sample(job, x, y, 0, 1, sum, key, &out);
  // As render_reference forms its pixel at one sample per pixel (inv_spp = 1).
  out.emissive = sum.emissive;
  out.ambient = sum.ambient;
  out.diffuse = sum.diffuse;
  out.specular = sum.specular;
  out.total = form_total(sum.emissive, sum.ambient, sum.diffuse, sum.specular,
                         missed_background(job, sum, 1.0));
  if (out.hit) {
    out.object_name = scene.objects[static_cast<std::size_t>(out.object)].name;
    if (out.material >= 0 && static_cast<std::size_t>(out.material) < scene.material_names.size()) {
      out.material_name = scene.material_names[static_cast<std::size_t>(out.material)];
    }
  }
  return out;
}

PixelBreakdown inspect_pixel(const Scene& scene, int x, int y) {
  return PixelInspector(scene).inspect(x, y);
}

}  // namespace gloss
