#include "editor/ui/panels/swatches.h"

#include <chrono>

#include "engine/renderer.h"
#include "io/image/image_io.h"
#include "io/material/preset_table.h"

namespace gloss {

namespace {

// A unit sphere filling most of the frame, lit from the upper right, on a dark grey background
// so that black materials stay visible.
Scene swatch_scene(const Material& material) {
  Scene scene;
  scene.camera.eye = {0.0f, 0.0f, 3.3f};
  scene.camera.fov_y = 40.0f;
  scene.background = glm::vec3(0.16f, 0.16f, 0.18f);
  scene.ambient = glm::vec3(0.2f);
  PointLight light;
  light.position = {2.5f, 3.0f, 4.0f};
  scene.lights.push_back(light);
  scene.materials.push_back(material);
  scene.material_names.push_back(material.preset.empty() ? "swatch" : material.preset);
  scene.objects.push_back(Object{});
  scene.render.width = Swatches::kSize;
  scene.render.height = Swatches::kSize;
  scene.render.spp = 4;
  scene.render.shadows = false;
  return scene;
}

std::vector<std::vector<unsigned char>> render_swatches() {
  std::vector<std::vector<unsigned char>> out;
  for (const Preset& preset : preset_table()) out.push_back(render_swatch(preset.material));
  return out;
}

}  // namespace

std::vector<unsigned char> render_swatch(const Material& material) {
  RenderOptions options;
  options.terms = false;
  const TermImages images = render(swatch_scene(material), options);
  std::vector<unsigned char> rgb;
  rgb.reserve(images.total.pixels.size() * 3);
  for (const glm::vec3& p : images.total.pixels) {
    rgb.push_back(encode_channel(p.x, false));
    rgb.push_back(encode_channel(p.y, false));
    rgb.push_back(encode_channel(p.z, false));
  }
  return rgb;
}

void Swatches::start() {
  m_job = std::async(std::launch::async, render_swatches);
}

void Swatches::poll() {
  if (!m_job.valid() || m_job.wait_for(std::chrono::seconds(0)) != std::future_status::ready) {
    return;
  }
  try {
    const std::vector<std::vector<unsigned char>> swatches = m_job.get();
    m_textures.resize(swatches.size());
    for (std::size_t i = 0; i < swatches.size(); ++i) {
      m_textures[i].upload_rgb8(kSize, kSize, swatches[i].data());
    }
  } catch (const std::exception& e) {
    m_error = e.what();
  }
}

GLuint Swatches::texture(std::size_t preset) const {
  return preset < m_textures.size() ? m_textures[preset].id() : 0;
}

}  // namespace gloss
