#pragma once
// Screenshot and export files: what goes into them and names that never replace a file. The
// viewport and term-sheet exports are rendered at the document's full resolution (scene.render),
// so they do not depend on the window's size or preview quality: by the CPU renderer here, by
// the raster path in the editor when it draws the viewport (editor/ui/parts/exports.cpp).
#include <ctime>
#include <filesystem>
#include <functional>
#include <string>

#include "base/image.h"
#include "display/display_transform.h"
#include "editor/model/view/view_settings.h"
#include "io/image/image_io.h"
#include "scene/scene.h"

namespace gloss {

// "20251121-101530" (local time).
std::string timestamp_text(std::time_t time);

// Writes a file named folder/PREFIX-TIMESTAMP.EXTENSION (extension with its dot), or
// PREFIX-TIMESTAMP-2.EXTENSION, -3 ... when the name is taken: write(temp) writes it under a
// temporary name, and the finished file is hard-linked into place, which fails instead of
// replacing, so two writers can never overwrite each other. Returns the path written; throws
// RuntimeFailure.
std::filesystem::path write_unique(const std::filesystem::path& folder, const std::string& prefix,
                                   const std::string& extension,
                                   const std::function<void(const std::string& temp)>& write,
                                   std::time_t time);
// write_unique of a PNG (write_png with the encoding alone: clamp, then as is or sRGB).
std::filesystem::path write_png_unique(const std::filesystem::path& folder,
                                       const std::string& prefix, const Image& image, bool srgb,
                                       const TextChunks& text, std::time_t time);

// The linear image through the document's exposure, tone curve and clamp (display_linear of
// display/display_transform.h): values in [0, 1] that the PNG writer's encoding (render.srgb)
// finishes. Exports apply it before drawing labels, so labels stay white under any transform.
Image exposed(const Image& image, const RenderSettings& render);

// The term sheet: emissive + ambient | diffuse on top, specular | total below, each W x H pane
// under a black strip of term_sheet_band(H) rows that names it in white (sheet_labels.h), so the
// sheet is 2W x 2(H + band) and every pane pixel is its term's own: linear, or with display its
// display_linear value (the labels are drawn after it, so they stay white).
Image term_sheet(const TermImages& terms, const DisplayTransform* display = nullptr);
int term_sheet_band(int pane_height);

// The single image the viewport kind exports: the total, or the term a single-term view shows.
Image viewport_image(const TermImages& terms, const ViewSettings& view);

// PNG text chunks that reproduce an export: the scene JSON and the view settings. view.renderer
// names the renderer that made the image (cpu or gl; with gl the raster knobs follow).
TextChunks export_text(const Scene& scene, const ViewSettings& view, ScreenshotKind kind);

// Whether an export of kind under view needs the four term images (the term sheet, one term).
bool export_needs_terms(const ViewSettings& view, ScreenshotKind kind);

// The image of kind from rendered terms (the raster path's frame, or render()'s images), render
// the document's settings: viewport and terms exposed (above), for the PNG writer's encoding;
// exr the linear image of the viewport kind (the total, or the single term shown).
Image export_image(const TermImages& terms, const ViewSettings& view, ScreenshotKind kind,
                   const RenderSettings& render);

// Renders scene with the CPU renderer at scene.render's size and spp and returns
// export_image() of it (window screenshots come from the GL back buffer). Throws like render().
Image render_export(const Scene& scene, const ViewSettings& view, ScreenshotKind kind);

// Writes image for a script's `screenshot PATH`: a PATH naming a folder (existing, or ending in
// '/') gets a unique timestamped name inside it; any other PATH is written atomically, replacing
// what was there. Returns the path written; throws RuntimeFailure.
std::filesystem::path write_export(const std::string& path, const Image& image, bool srgb,
                                   const TextChunks& text);
// The same for an exr export: the linear image as OpenEXR (io/image/exr_writer.h).
std::filesystem::path write_exr_export(const std::string& path, const Image& image);
// Where an export of kind goes when no path is given: folder/gloss-KIND-TIMESTAMP.png (.exr).
std::filesystem::path write_export_in(const std::filesystem::path& folder, ScreenshotKind kind,
                                      const Image& image, bool srgb, const TextChunks& text);

}  // namespace gloss
