#pragma once
// Screenshot and export files: what goes into them and names that never replace a file. The
// viewport and term-sheet exports are rendered at the document's full resolution (scene.render),
// so they do not depend on the window's size or preview quality: by the CPU renderer here, by
// the raster path in the editor when it draws the viewport (editor/ui/parts/exports.cpp).
#include <ctime>
#include <filesystem>
#include <string>

#include "base/image.h"
#include "editor/model/view/view_settings.h"
#include "io/image/image_io.h"
#include "scene/scene.h"

namespace gloss {

// "20251121-101530" (local time).
std::string timestamp_text(std::time_t time);

// Writes a PNG named folder/PREFIX-TIMESTAMP.png, or PREFIX-TIMESTAMP-2.png, -3 ... when the name
// is taken. The finished file is hard-linked into place, which fails instead of replacing, so
// two writers can never overwrite each other. Returns the path written; throws RuntimeFailure.
std::filesystem::path write_png_unique(const std::filesystem::path& folder,
                                       const std::string& prefix, const Image& image, bool srgb,
                                       const TextChunks& text, std::time_t time);

// Linear values times 2^stops (the viewport's exposure).
Image exposed(const Image& image, float stops);

// The term sheet: emissive + ambient | diffuse on top, specular | total below, each W x H pane
// under a black strip of term_sheet_band(H) rows that names it in white (sheet_labels.h), so the
// sheet is 2W x 2(H + band) and every pane pixel is its term's own.
Image term_sheet(const TermImages& terms);
int term_sheet_band(int pane_height);

// The single image the viewport kind exports: the total, or the term a single-term view shows.
Image viewport_image(const TermImages& terms, const ViewSettings& view);

// PNG text chunks that reproduce an export: the scene JSON and the view settings. view.renderer
// names the renderer that made the image (cpu or gl; with gl the raster knobs follow).
TextChunks export_text(const Scene& scene, const ViewSettings& view, ScreenshotKind kind);

// Whether an export of kind under view needs the four term images (the term sheet, one term).
bool export_needs_terms(const ViewSettings& view, ScreenshotKind kind);

// The exposed image of kind (viewport or terms) from rendered terms (the raster path's frame,
// or render()'s images).
Image export_image(const TermImages& terms, const ViewSettings& view, ScreenshotKind kind);

// Renders scene with the CPU renderer at scene.render's size and spp and returns
// export_image() of it (window screenshots come from the GL back buffer). Throws like render().
Image render_export(const Scene& scene, const ViewSettings& view, ScreenshotKind kind);

// Writes image for a script's `screenshot PATH`: a PATH naming a folder (existing, or ending in
// '/') gets a unique timestamped name inside it; any other PATH is written atomically, replacing
// what was there. Returns the path written; throws RuntimeFailure.
std::filesystem::path write_export(const std::string& path, const Image& image, bool srgb,
                                   const TextChunks& text);

}  // namespace gloss
