#pragma once
// `screenshot PATH shown`: the frame the viewport shows, as it is, at its own size (the pane's,
// or a preview's), not rendered again. PATH ending in .pfm gets the linear floats (no exposure,
// no encoding: what the renderer computed); .png gets the displayed values (exposure, then the
// document's encoding) with the scene in its text chunks, its render size set to the frame's, so
// `gloss-cli render SHOT.png` renders the image the viewport showed. A folder gets a timestamped
// PNG. The image is the total, the single term shown, or in the term views the term sheet; in
// A/B the A side.
#include <filesystem>
#include <string>

#include "base/image.h"
#include "editor/model/view/view_settings.h"
#include "engine/progressive_renderer.h"
#include "scene/scene.h"

namespace gloss {

// Whether PATH names a file a shown screenshot can be (.png or .pfm, any case) or a folder.
bool shown_path_ok(const std::string& path);

// The linear image the viewport shows of frame in view (not exposed).
Image shown_image(const RenderedFrame& frame, const ViewSettings& view);

// Writes the shown frame to path (atomically), scene the document the frame belongs to and
// raster whether the raster path drew it. Returns the path written; throws RuntimeFailure.
std::filesystem::path write_shown(const std::string& path, const RenderedFrame& frame,
                                  const Scene& scene, const ViewSettings& view, bool raster);

}  // namespace gloss
