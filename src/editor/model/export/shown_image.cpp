#include "editor/model/export/shown_image.h"

#include <cstdio>
#include <ctime>
#include <string_view>

#include "base/text/ascii.h"
#include "base/error.h"
#include "editor/model/export/export_image.h"
#include "io/image/image_io.h"

namespace gloss {

namespace {
bool ends_with(const std::string& path, const char* extension) {
  const std::string e = extension;
  if (path.size() < e.size()) return false;
  return ascii_equal_ignoring_case(std::string_view(path).substr(path.size() - e.size()), e);
}

bool is_folder(const std::string& path) {
  std::error_code error;
  return (!path.empty() && path.back() == '/') || std::filesystem::is_directory(path, error);
}
}  // namespace

bool shown_path_ok(const std::string& path) {
  return ends_with(path, ".png") || ends_with(path, ".pfm") || is_folder(path);
}

Image shown_image(const RenderedFrame& frame, const ViewSettings& view) {
  const TermImages& images = frame.images;
  const bool terms = images.emissive.width > 0;
  if (view.mode == ViewMode::terms && terms) return term_sheet(images);
  if (view.mode == ViewMode::single && !terms) return images.total;  // terms not published yet
  return viewport_image(images, view);
}

std::filesystem::path write_shown(const std::string& path, const RenderedFrame& frame,
                                  const Scene& scene, const ViewSettings& view, bool raster) {
  const Image linear = shown_image(frame, view);
  if (linear.width <= 0) throw RuntimeFailure("no frame is shown yet");
  if (ends_with(path, ".pfm") && !is_folder(path)) {
    std::error_code error;
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    if (!parent.empty()) std::filesystem::create_directories(parent, error);
    write_pfm(path, linear);
    return path;
  }
  // The scene as the frame was rendered: the document at the frame's size.
  Scene at_size = scene;
  at_size.render.width = frame.info.width;
  at_size.render.height = frame.info.height;
  ViewSettings v = view;
  v.renderer = raster ? RendererChoice::gl : RendererChoice::cpu;
  TextChunks text = export_text(at_size, v, ScreenshotKind::shown);
  char shown[96];
  std::snprintf(shown, sizeof shown, " shown_spp=%d converged=%s", frame.info.spp,
                frame.info.converged ? "yes" : "no");
  for (auto& [keyword, value] : text) {
    if (keyword == "gloss:settings") value += shown;
  }
  const Image display = exposed(linear, scene.render);  // the display transform, before encoding
  if (is_folder(path)) {
    return write_png_unique(path, "gloss-shown", display, scene.render.srgb, text,
                            std::time(nullptr));
  }
  return write_export(path, display, scene.render.srgb, text);
}

}  // namespace gloss
