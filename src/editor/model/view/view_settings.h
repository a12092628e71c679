#pragma once
// How the editor shows the document: view mode, preview quality, the pixel inspector. These are
// preferences of the window, not part of the document, so they are not undone. The display
// transform (render.exposure, render.tone, render.srgb) is the document's: the viewport,
// screenshots, exports and gloss-cli all follow it (display/display_transform.h).
#include <string>

#include "editor/model/view/gizmo.h"
#include "editor/model/view/raster_settings.h"
#include "scene/scene.h"

namespace gloss {

// render: the total image; terms: emissive+ambient, diffuse, specular and total in a 2x2 sheet;
// single: one term alone; ab: Phong against Blinn-Phong with a difference heat map; lobe: the
// selected material's reflected radiance in the plane of incidence (analysis/lobe/brdf_lobe.h).
enum class ViewMode { render, terms, single, ab, lobe };
const char* to_string(ViewMode mode);
bool parse_view_mode(const std::string& name, ViewMode& mode);

// The images a pane can show. emissive_ambient is the sum of those two term buffers.
enum class TermView { emissive_ambient, emissive, ambient, diffuse, specular, total };
const char* to_string(TermView term);
const char* display_name(TermView term);  // "emissive + ambient"
bool parse_term_view(const std::string& name, TermView& term);

// What the A/B view compares (ab_compare.h): the document as Phong | Blinn-Phong, the snapshot
// taken with Snapshot | the live document, the ray tracer at 1 spp | the raster path (cpu_gl), or
// the raster path per pixel | per vertex (pixel_vertex).
// reference: the material (Phong or Blinn-Phong, as the scene) against its physical reference
// (docs/spec/physical-reference.md), both at 1 spp.
enum class AbSource { models, snapshot, cpu_gl, pixel_vertex, reference };

// viewport and terms render the document again at its size, through the display transform, as
// PNG; window reads the window back; shown writes the frame the viewport shows as it is
// (shown_image.h); exr is the viewport's linear image (before the transform) as 32-bit float
// OpenEXR.
enum class ScreenshotKind { viewport, terms, window, shown, exr };
const char* to_string(ScreenshotKind kind);
bool parse_screenshot_kind(const std::string& name, ScreenshotKind& kind);

// Energy normalisation of the lobe view's curves: as the document's render.energy_normalize, or
// forced on or off for the view alone (the document is not changed).
enum class LobeEnergy { scene, on, off };

// What the lobe view plots: the plane of incidence (polar), the whole hemisphere of outgoing
// directions (3D), or the directional albedo against the incidence angle.
enum class LobePlot { plane, hemisphere, albedo };
const char* to_string(LobePlot plot);
bool parse_lobe_plot(const std::string& name, LobePlot& plot);

// The lobe view's second material, drawn over the selected one's: none, the snapshot's material
// of the same object (the A side of the snapshot A/B view), a material of the document or a
// preset, by name (lobe_overlay.h resolves it).
enum class LobeOverlay { none, snapshot, material, preset };

struct ViewSettings {
  ViewMode mode = ViewMode::render;
  // Which renderer draws the viewport (raster_settings.h) and the raster path's knobs.
  RendererChoice renderer = RendererChoice::cpu;
  RasterSettings raster;
  TermView single = TermView::specular;   // shown by ViewMode::single
  bool heat_auto_scale = true;            // heat scale = largest difference of the shown pair
  float heat_scale = 0.1f;                // linear difference at the top of the heat ramp, > 0
  float preview_scale = 1.0f;             // render pixels per screen pixel, 0.25..1
  AbSource ab_source = AbSource::models;  // what ViewMode::ab compares
  // One setting for two uses: the model switch rescales every exponent by document.h's rule,
  // and the Phong | Blinn-Phong A/B view renders B with the rescaled exponents.
  bool keep_highlight_size = true;
  bool show_clipped = false;  // stripes over clipped pixels (exposure_histogram.h)
  // Every object with the UV checker (texture/uv_checker.h) on its (u, v) instead of its
  // material: a way to see a model's coordinates. The renderers get scene_as_viewed().
  bool uv_checker = false;
  bool orbit_light = false;   // animate the selected light about the target's y axis
  float orbit_speed = 45.0f;  // degrees per second
  ScreenshotKind screenshot_kind = ScreenshotKind::viewport;  // what Ctrl+S saves
  std::string screenshot_dir = ".";  // where Ctrl+S writes its timestamped files

  // The lobe view (ViewMode::lobe).
  float lobe_elevation_deg = 45.0f;  // light above the surface, degrees, 0..90
  LobeEnergy lobe_energy = LobeEnergy::scene;
  LobePlot lobe_plot = LobePlot::plane;
  LobeOverlay lobe_overlay = LobeOverlay::none;
  std::string lobe_overlay_name;   // LobeOverlay::material and ::preset: which one
  float lobe_azimuth_deg = 35.0f;  // the 3D plot's camera about the normal, degrees
  float lobe_tilt_deg = 25.0f;     // ... above the surface, degrees, -10..89
  // The plot's radius on a logarithmic scale (three decades below the largest value), so a
  // physical reference's bright peak and a Phong lobe of ks <= 1 read in one plot.
  bool lobe_log_radius = false;

  // The transform gizmo over the selected objects (gizmo.h): move, rotate or scale (W, E, R).
  GizmoMode gizmo = GizmoMode::move;
  bool show_gizmo = true;

  // The pixel inspector: a pixel of the document's render size, read at its centre.
  bool show_inspector = false;
  bool inspect_pinned = false;  // false: the inspector follows the cursor over the viewport
  int inspect_x = 0, inspect_y = 0;
};

// The scene the renderers are handed for the document in this view: the document itself, or
// with the UV checker on, the document with every material replaced by the checker material
// (uv_checker_material). The document is not changed: a view setting, not an edit.
Scene scene_as_viewed(const Scene& document, const ViewSettings& view);

// The UV checker view's material: kd 1 times the checker on (u, v) set 0 (and ka 0.15 times
// it, so unlit sides still show their cells), no specular, emission or other map, no physical
// reference: the cells as the lights show them, nothing of the document's material.
Material uv_checker_material();

// Whether the lobe view normalises: document_setting is render.energy_normalize.
bool lobe_energy_normalize(LobeEnergy energy, bool document_setting);

}  // namespace gloss
