#include "editor/ui/parts/exports.h"

#include <chrono>
#include <cstdio>
#include <ctime>

#include <glad/gl.h>

#include "editor/model/export/export_image.h"
#include "editor/model/export/shown_image.h"
#include "editor/ui/parts/commands.h"
#include "editor/ui/shortcuts.h"
#include "editor/ui/viewport/viewport.h"

namespace gloss {

void Exports::start(ScreenshotKind kind, const std::string& path, bool from_script) {
  if (kind == ScreenshotKind::window) {
    m_capture = {true, path, from_script, from_script ? 0 : 1};
    if (!from_script) close_menus();
    return;
  }
  if (kind == ScreenshotKind::shown) {
    // The frame on screen as it is, written on a worker (shown_image.h).
    PendingExport job;
    job.from_script = from_script;
    job.path = std::async(std::launch::async,
                          [frame = m_viewport.shown_images(), scene = m_commands.scene(),
                           view = m_view, raster = m_viewport.shown_raster_a(), path] {
                            if (frame == nullptr) throw std::runtime_error("no frame is shown yet");
                            return write_shown(path.empty() ? view.screenshot_dir + "/" : path,
                                               *frame, scene, view, raster);
                          });
    m_pending.push_back(std::move(job));
    return;
  }
  const Scene scene = m_commands.scene();
  ViewSettings view = m_view;
  // The raster path draws the viewport: the export is its frame at the document's size, drawn
  // here (it needs the GL context) and written on the worker. Automatic exports the still image,
  // the ray tracer's.
  std::shared_ptr<const RenderedFrame> raster;
  std::string raster_error;
  if (view.renderer == RendererChoice::gl) {
    try {
      raster = m_viewport.render_raster(scene, view.raster, export_needs_terms(view, kind));
      if (!raster) raster_error = "the raster path is unavailable (see the notice)";
    } catch (const std::exception& e) {
      raster_error = std::string("the raster path failed: ") + e.what();
    }
  } else {
    view.renderer = RendererChoice::cpu;
  }
  PendingExport job;
  job.from_script = from_script;
  job.path = std::async(std::launch::async, [scene, view, kind, path, raster, raster_error] {
    if (!raster_error.empty()) throw std::runtime_error(raster_error);
    const Image image = raster ? export_image(raster->images, view, kind, scene.render)
                               : render_export(scene, view, kind);
    const TextChunks text = export_text(scene, view, kind);
    if (path.empty()) {
      return write_export_in(view.screenshot_dir, kind, image, scene.render.srgb, text);
    }
    if (kind == ScreenshotKind::exr) return write_exr_export(path, image);
    return write_export(path, image, scene.render.srgb, text);
  });
  m_pending.push_back(std::move(job));
  if (!from_script)
    m_commands.info(std::string("rendering the ") + to_string(kind) +
                    " screenshot at full resolution ...");
}

bool Exports::poll() {
  bool script_failed = false;
  for (auto it = m_pending.begin(); it != m_pending.end();) {
    if (it->path.wait_for(std::chrono::seconds(0)) != std::future_status::ready) {
      ++it;
      continue;
    }
    try {
      const std::filesystem::path written = it->path.get();
      const std::string absolute = std::filesystem::absolute(written).lexically_normal().string();
      m_commands.info("saved screenshot " + absolute);
      if (it->from_script) std::printf("saved %s\n", absolute.c_str());
    } catch (const std::exception& e) {
      m_commands.error(std::string("screenshot failed: ") + e.what());
      if (it->from_script) script_failed = true;
    }
    std::fflush(stdout);
    it = m_pending.erase(it);
  }
  return script_failed;
}

void Exports::capture_if_due(GLFWwindow* window) {
  if (m_capture.requested && m_capture.frames_to_skip-- <= 0) capture_window(window);
}

void Exports::capture_window(GLFWwindow* window) {
  int width = 0, height = 0;
  glfwGetFramebufferSize(window, &width, &height);
  std::vector<unsigned char> rgb(static_cast<std::size_t>(width) * height * 3);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_BACK);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
  // GL rows run bottom to top; images top to bottom. 8-bit values map exactly back through the
  // PNG writer's clamp-and-round (v / 255 * 255 rounds to v).
  Image image(width, height);
  for (int y = 0; y < height; ++y) {
    const unsigned char* row = &rgb[static_cast<std::size_t>(height - 1 - y) * width * 3];
    for (int x = 0; x < width; ++x) {
      image.at(x, y) = glm::vec3(row[3 * x], row[3 * x + 1], row[3 * x + 2]) / 255.0f;
    }
  }
  const WindowCapture capture = m_capture;
  m_capture = {};
  const ViewSettings view = m_view;
  const TextChunks text = export_text(m_commands.scene(), view, ScreenshotKind::window);
  PendingExport job;
  job.from_script = capture.from_script;
  job.path = std::async(std::launch::async, [image, text, capture, view] {
    if (capture.path.empty()) {
      return write_png_unique(view.screenshot_dir, "gloss-window", image, false, text,
                              std::time(nullptr));
    }
    return write_export(capture.path, image, false, text);
  });
  m_pending.push_back(std::move(job));
}

bool Exports::finish() {
  bool ok = true;
  for (PendingExport& job : m_pending) {
    try {
      std::printf("saved %s\n", job.path.get().string().c_str());
    } catch (const std::exception& e) {
      std::fprintf(stderr, "error: %s\n", e.what());
      ok = false;
    }
  }
  return ok;
}

}  // namespace gloss
