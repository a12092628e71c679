#pragma once
// What panels keep between frames that is neither the document nor a view setting: one struct
// per panel that needs one, owned by the App and handed to that panel alone.
#include <cstdint>
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "editor/gl/raster/raster_tradeoff.h"
#include "editor/model/document/reference_fit.h"
#include "editor/model/measure/quality_measurement.h"
#include "editor/model/view/view_settings.h"
#include "editor/ui/panels/map_thumbnails.h"
#include "reference/pixel_inspection.h"

namespace gloss {

// The Material panel.
struct MaterialPanelState {
  bool link_channels = false;  // colour editors move R, G, B together
  MapThumbnails thumbnails;    // the map slots' previews
  std::string name_field;      // the selected material's name field
  int name_field_material = -1;
  int renaming = -1;  // the material being renamed in the list, -1 none
  std::string rename_text;
  bool focus_rename = false;
};

// The Outliner (outliner_panel.cpp): its filter, the name being edited in place, the anchor of
// Shift+click ranges.
struct OutlinerState {
  std::string filter;       // only names holding it are listed (any case)
  int renaming = -1;        // the object whose name is being edited in the list, -1 none
  std::string rename_text;  // the name being typed
  bool focus_rename = false;
  int anchor = -1;         // the last object clicked without Shift
  std::string name_field;  // the selected object's name field
  int name_field_object = -1;
};

// The Reference panel: a fit in flight on a worker (a fraction of a second; the UI keeps drawing)
// and what the last one found.
struct ReferencePanelState {
  std::future<ReferenceFit> job;  // valid() while a fit runs
  ShadingModel job_model = ShadingModel::phong;
  LobeMetric metric = LobeMetric::l2;  // what Fit minimises
  std::vector<std::string> report;     // the last applied fit's constants and residuals
  PhysicalReference last_reference;    // a reference to give a material that has none
  // How far the selected material is from its reference now, recomputed on a worker whenever
  // the material, its reference, the model or the energy switch change (a few tens of ms).
  std::future<LobeResidual> residual_job;
  std::string residual_key;  // what residual (or residual_job, while it runs) is for
  std::optional<LobeResidual> residual;
};

// The pixel inspector's readers (inspector_panel.cpp); the pixel under the cursor is the
// viewport's (Viewport::hover_x).
struct InspectorState {
  std::unique_ptr<PixelInspector> a, b;  // the document (A/B view: its Phong and Blinn sides)
  std::uint64_t revision = 0;            // document revision they were built for
  bool ab = false, keep = false;         // the A/B split and exponent rule they were built for
  AbSource source = AbSource::models;    // what the A/B compared (ab_compare.h)
  std::uint64_t snapshot = 0;            // the snapshot's revision + 1 they were built for, 0 none
  std::string error;                     // why they could not be built
};

// The Quality window's measurements (quality_panel.cpp, quality_parts.h).
struct QualityState {
  QualityMeasurement cpu;         // the ray tracer's knobs, measured on a worker
  RasterTradeoff raster;          // the raster (GLSL) rows, drawn on the UI thread
  bool show_raster_rows = false;  // select the raster tab on the window's next frame
};

}  // namespace gloss
