// The viewport's raster path (issue 12): which sides it draws, the renderer built on the UI
// thread when first needed, and its frames handed to the same textures as the ray tracer's, so
// term views, A/B, the inspector, the histogram and screenshots read them alike.
#include <exception>
#include <string>

#include <GLFW/glfw3.h>
#include <glad/gl.h>

#include "editor/ui/viewport/viewport.h"

namespace gloss {

bool Viewport::RasterKey::same_setup(const RasterKey& o) const {
  return width == o.width && height == o.height && terms == o.terms && ab == o.ab &&
         keep == o.keep && source == o.source && sides.a == o.sides.a && sides.b == o.sides.b &&
         settings == o.settings && lights == o.lights;
}

bool Viewport::RasterKey::operator==(const RasterKey& o) const {
  return revision == o.revision && snapshot == o.snapshot && same_setup(o);
}

bool Viewport::raster_available() {
  if (m_raster) return true;
  if (m_raster_failed) return false;
  try {
    m_raster = std::make_unique<RasterRenderer>();
    reset_gl_state();
    return true;
  } catch (const std::exception& e) {
    m_raster_failed = true;
    m_raster_notice = std::string("raster (GLSL) unavailable, the ray tracer draws: ") + e.what();
    reset_gl_state();
    return false;
  }
}

bool Viewport::raster_effective(const ViewSettings& view, double now_s) {
  switch (view.renderer) {
    case RendererChoice::cpu:
      return false;
    case RendererChoice::gl:
      return raster_available();
    case RendererChoice::automatic:
      return moving_gesture(now_s) && raster_available() && m_automatic.raster_for(m_setup);
  }
  return false;
}

Viewport::AutomaticReport Viewport::automatic_report() const {
  return {m_automatic.would_raster(m_setup), m_automatic.raster_ms(m_setup),
          m_automatic.ray_traced_ms(m_setup), m_automatic.ray_traced_pass_ms(m_setup)};
}

std::string Viewport::take_raster_notice() {
  std::string notice;
  notice.swap(m_raster_notice);
  return notice;
}

void Viewport::reset_gl_state() {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glDepthMask(GL_TRUE);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glUseProgram(0);
  glBindVertexArray(0);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, 0);
}

bool Viewport::show_raster(const AbScenes& scenes, const AbSides& sides,
                           const RasterSettings& settings, bool terms, bool ab, double now_s) {
  try {
    if (sides.a.raster) {
      RasterSettings a = settings;
      a.shading = sides.a.shading;
      std::shared_ptr<const RenderedFrame> frame = m_raster->render(scenes.a, a, terms && !ab);
      reset_gl_state();
      upload(*frame, false);
      m_frame_a = m_image_a = std::move(frame);
      m_shown_raster_a = true;
    }
    if (ab && sides.b.raster) {
      RasterSettings b = settings;
      b.shading = sides.b.shading;
      std::shared_ptr<const RenderedFrame> frame = m_raster->render(scenes.b, b, false);
      reset_gl_state();
      upload(*frame, true);
      m_frame_b = m_image_b = std::move(frame);
      m_shown_raster_b = true;
    }
  } catch (const std::exception& e) {
    // The caller hands this state to the ray tracer; a repeated message is not announced again
    // (a drag in automatic mode tries every frame).
    reset_gl_state();
    const std::string message = std::string("raster path: ") + e.what() + "; ray traced instead";
    if (message != m_raster_last_error) m_raster_notice = message;
    m_raster_last_error = message;
    m_raster_shown = false;
    return false;
  }
  m_raster_last_error.clear();
  m_raster_shown = true;
  max_difference_of_shown();
  // The newest edit's first image, also its full-size one.
  m_show_pending = true;
  m_show_generation = ImageCadence::kNewest;
  m_show_full = true;
  (void)now_s;
  glfwPostEmptyEvent();  // the next frame draws the new textures
  return true;
}

std::shared_ptr<const RenderedFrame> Viewport::render_raster(const Scene& scene,
                                                             const RasterSettings& settings,
                                                             bool terms) {
  if (!raster_available()) return nullptr;
  std::shared_ptr<const RenderedFrame> frame = m_raster->render(scene, settings, terms);
  reset_gl_state();
  return frame;
}

}  // namespace gloss
