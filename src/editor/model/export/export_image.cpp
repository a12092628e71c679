#include "editor/model/export/export_image.h"

#include "editor/model/export/sheet_labels.h"

#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <system_error>

#include "base/error.h"
#include "engine/renderer.h"
#include "io/image/exr_writer.h"
#include "io/image/scene_in_png.h"

namespace gloss {

std::string timestamp_text(std::time_t time) {
  std::tm tm{};
  localtime_r(&time, &tm);
  char text[32];
  std::strftime(text, sizeof text, "%Y%m%d-%H%M%S", &tm);
  return text;
}

std::filesystem::path write_unique(const std::filesystem::path& folder, const std::string& prefix,
                                   const std::string& extension,
                                   const std::function<void(const std::string& temp)>& write,
                                   std::time_t time) {
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  const std::string stem = prefix + "-" + timestamp_text(time);
  const std::filesystem::path temp =
      folder / ("." + stem + ".tmp-" + std::to_string(static_cast<long>(::getpid())) + extension);
  write(temp.string());
  for (int n = 1; n < 10000; ++n) {
    const std::filesystem::path candidate =
        folder / (n == 1 ? stem + extension : stem + "-" + std::to_string(n) + extension);
    if (::link(temp.c_str(), candidate.c_str()) == 0) {
      std::filesystem::remove(temp, error);
      return candidate;
    }
    if (errno != EEXIST) {
      const std::string reason = std::strerror(errno);
      std::filesystem::remove(temp, error);
      throw RuntimeFailure("cannot write " + candidate.string() + ": " + reason);
    }
  }
  std::filesystem::remove(temp, error);
  throw RuntimeFailure("no free file name for " + (folder / stem).string());
}

std::filesystem::path write_png_unique(const std::filesystem::path& folder,
                                       const std::string& prefix, const Image& image, bool srgb,
                                       const TextChunks& text, std::time_t time) {
  return write_unique(
      folder, prefix, ".png", [&](const std::string& temp) { write_png(temp, image, srgb, text); },
      time);
}

Image exposed(const Image& image, const RenderSettings& render) {
  return displayed_image(image, display_transform(render), false);
}

int term_sheet_band(int pane_height) {
  const int scale = std::max(1, pane_height / 200);  // 2x font from 400-pixel panes up
  return label_height(scale) + 4 * scale;
}

Image term_sheet(const TermImages& terms, const DisplayTransform* display) {
  const int w = terms.total.width, h = terms.total.height;
  const int band = term_sheet_band(h);
  const int scale = std::max(1, h / 200);
  Image sheet(2 * w, 2 * (h + band));
  Image emissive_ambient = terms.emissive;
  for (std::size_t i = 0; i < emissive_ambient.pixels.size(); ++i) {
    emissive_ambient.pixels[i] += terms.ambient.pixels[i];
  }
  const Image* panes[4] = {&emissive_ambient, &terms.diffuse, &terms.specular, &terms.total};
  const char* names[4] = {"emissive + ambient", "diffuse", "specular", "total"};
  for (int pane = 0; pane < 4; ++pane) {
    const int ox = (pane % 2) * w, oy = (pane / 2) * (h + band) + band;
    const Image shown =
        display != nullptr ? displayed_image(*panes[pane], *display, false) : *panes[pane];
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) sheet.at(ox + x, oy + y) = shown.at(x, y);
    }
    draw_label(sheet, ox + 4 * scale, oy - band + 2 * scale, names[pane], glm::vec3(1.0f), scale);
  }
  return sheet;
}

Image viewport_image(const TermImages& terms, const ViewSettings& view) {
  if (view.mode != ViewMode::single) return terms.total;
  switch (view.single) {
    case TermView::emissive_ambient: {
      Image sum = terms.emissive;
      for (std::size_t i = 0; i < sum.pixels.size(); ++i) sum.pixels[i] += terms.ambient.pixels[i];
      return sum;
    }
    case TermView::emissive:
      return terms.emissive;
    case TermView::ambient:
      return terms.ambient;
    case TermView::diffuse:
      return terms.diffuse;
    case TermView::specular:
      return terms.specular;
    case TermView::total:
      break;
  }
  return terms.total;
}

TextChunks export_text(const Scene& scene, const ViewSettings& view, ScreenshotKind kind) {
  char settings[256];
  std::snprintf(settings, sizeof settings,
                "kind=%s model=%s spp=%d size=%dx%d exposure=%g tone=%s encoding=%s shadows=%s "
                "energy_normalize=%s term=%s",
                to_string(kind), to_string(scene.render.model), scene.render.spp,
                scene.render.width, scene.render.height, static_cast<double>(scene.render.exposure),
                to_string(scene.render.tone), scene.render.srgb ? "srgb" : "clamp",
                scene.render.shadows ? "on" : "off", scene.render.energy_normalize ? "on" : "off",
                view.mode == ViewMode::single ? to_string(view.single) : "total");
  std::string line = settings;
  if (view.renderer == RendererChoice::gl) {
    // One sample per pixel at the centre, whatever spp says (raster_renderer.h).
    std::snprintf(settings, sizeof settings, " renderer=gl shading=%s shadow_map=%d shadow_bias=%g",
                  to_string(view.raster.shading), view.raster.shadow_map_size,
                  view.raster.shadow_bias);
    line += settings;
  } else {
    line += " renderer=cpu";
  }
  return {{"Software", "gloss editor"},
          {"gloss:settings", line},
          {kSceneChunkKeyword, embedded_scene_text(scene)}};
}

bool export_needs_terms(const ViewSettings& view, ScreenshotKind kind) {
  // exr is the viewport kind's image, linear.
  return kind == ScreenshotKind::terms ||
         (view.mode == ViewMode::single && view.single != TermView::total);
}

Image render_export(const Scene& scene, const ViewSettings& view, ScreenshotKind kind) {
  RenderOptions options;
  options.terms = export_needs_terms(view, kind);
  return export_image(render(scene, options), view, kind, scene.render);
}

Image export_image(const TermImages& terms, const ViewSettings& view, ScreenshotKind kind,
                   const RenderSettings& render) {
  if (kind == ScreenshotKind::exr) return viewport_image(terms, view);
  if (kind == ScreenshotKind::terms) {
    // The transform applies to the terms, not to the white labels drawn between them.
    const DisplayTransform display = display_transform(render);
    return term_sheet(terms, &display);
  }
  return exposed(viewport_image(terms, view), render);
}

std::filesystem::path write_exr_export(const std::string& path, const Image& image) {
  std::error_code error;
  const bool folder =
      (!path.empty() && path.back() == '/') || std::filesystem::is_directory(path, error);
  if (folder) {
    return write_unique(
        path, "gloss", ".exr", [&](const std::string& temp) { write_exr(temp, image); },
        std::time(nullptr));
  }
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent, error);
  write_exr(path, image);
  return path;
}

std::filesystem::path write_export_in(const std::filesystem::path& folder, ScreenshotKind kind,
                                      const Image& image, bool srgb, const TextChunks& text) {
  const std::string prefix = std::string("gloss-") + to_string(kind);
  if (kind == ScreenshotKind::exr) {
    return write_unique(
        folder, prefix, ".exr", [&](const std::string& temp) { write_exr(temp, image); },
        std::time(nullptr));
  }
  return write_png_unique(folder, prefix, image, srgb, text, std::time(nullptr));
}

std::filesystem::path write_export(const std::string& path, const Image& image, bool srgb,
                                   const TextChunks& text) {
  std::error_code error;
  const bool folder =
      (!path.empty() && path.back() == '/') || std::filesystem::is_directory(path, error);
  if (folder) return write_png_unique(path, "gloss", image, srgb, text, std::time(nullptr));
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent, error);
  write_png(path, image, srgb, text);
  return path;
}

}  // namespace gloss
