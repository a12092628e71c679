#include "editor/model/export/export_image.h"

#include "editor/model/export/sheet_labels.h"

#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <system_error>

#include "base/error.h"
#include "engine/renderer.h"
#include "io/image/scene_in_png.h"

namespace gloss {

std::string timestamp_text(std::time_t time) {
  std::tm tm{};
  localtime_r(&time, &tm);
  char text[32];
  std::strftime(text, sizeof text, "%Y%m%d-%H%M%S", &tm);
  return text;
}

std::filesystem::path write_png_unique(const std::filesystem::path& folder,
                                       const std::string& prefix, const Image& image, bool srgb,
                                       const TextChunks& text, std::time_t time) {
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  const std::string stem = prefix + "-" + timestamp_text(time);
  const std::filesystem::path temp =
      folder / ("." + stem + ".tmp-" + std::to_string(static_cast<long>(::getpid())) + ".png");
  write_png(temp.string(), image, srgb, text);
  for (int n = 1; n < 10000; ++n) {
    const std::filesystem::path candidate =
        folder / (n == 1 ? stem + ".png" : stem + "-" + std::to_string(n) + ".png");
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

Image exposed(const Image& image, float stops) {
  Image out = image;
  const float gain = std::exp2(stops);
  for (glm::vec3& p : out.pixels) p *= gain;
  return out;
}

int term_sheet_band(int pane_height) {
  const int scale = std::max(1, pane_height / 200);  // 2x font from 400-pixel panes up
  return label_height(scale) + 4 * scale;
}

Image term_sheet(const TermImages& terms) {
  const int w = terms.total.width, h = terms.total.height;
  const int band = term_sheet_band(h);
  const int scale = std::max(1, h / 200);
  Image sheet(2 * w, 2 * (h + band));
  const Image* panes[4] = {&terms.emissive, &terms.diffuse, &terms.specular, &terms.total};
  const char* names[4] = {"emissive + ambient", "diffuse", "specular", "total"};
  for (int pane = 0; pane < 4; ++pane) {
    const int ox = (pane % 2) * w, oy = (pane / 2) * (h + band) + band;
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        glm::vec3 v = panes[pane]->at(x, y);
        if (pane == 0) v += terms.ambient.at(x, y);
        sheet.at(ox + x, oy + y) = v;
      }
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
                "kind=%s model=%s spp=%d size=%dx%d exposure=%g encoding=%s shadows=%s "
                "energy_normalize=%s term=%s",
                to_string(kind), to_string(scene.render.model), scene.render.spp,
                scene.render.width, scene.render.height, view.exposure,
                scene.render.srgb ? "srgb" : "clamp", scene.render.shadows ? "on" : "off",
                scene.render.energy_normalize ? "on" : "off",
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
  return kind == ScreenshotKind::terms ||
         (view.mode == ViewMode::single && view.single != TermView::total);
}

Image render_export(const Scene& scene, const ViewSettings& view, ScreenshotKind kind) {
  RenderOptions options;
  options.terms = export_needs_terms(view, kind);
  return export_image(render(scene, options), view, kind);
}

Image export_image(const TermImages& terms, const ViewSettings& view, ScreenshotKind kind) {
  if (kind == ScreenshotKind::terms) {
    if (view.exposure == 0.0f) return term_sheet(terms);
    // Exposure applies to the terms, not to the labels drawn between them.
    TermImages e;
    e.emissive = exposed(terms.emissive, view.exposure);
    e.ambient = exposed(terms.ambient, view.exposure);
    e.diffuse = exposed(terms.diffuse, view.exposure);
    e.specular = exposed(terms.specular, view.exposure);
    e.total = exposed(terms.total, view.exposure);
    return term_sheet(e);
  }
  const Image image = viewport_image(terms, view);
  return view.exposure == 0.0f ? image : exposed(image, view.exposure);
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
