#pragma once
// The raster path's knobs as tradeoff rows (issue 12, item 5): which settings are measured, what
// a row holds, and its CSV. GL-free; raster_tradeoff.h measures them. Rows are measured against
// the same exact reference as gloss-cli tradeoff's (analysis/tradeoff/tradeoff.h:
// render_reference<double> at reference_spp, the teapot at its finest level, per-pixel, full size,
// shadows as the scene says; error over every pixel of the total image), so they can be plotted
// with its rows (scripts/plot_tradeoff.py takes both CSVs).
#include <atomic>
#include <string>
#include <vector>

#include "analysis/image/image_metrics.h"
#include "analysis/tradeoff/tradeoff.h"
#include "editor/model/view/raster_settings.h"
#include "scene/scene.h"

namespace gloss {

// A pixel agrees with the one-sample exact image when every channel of its total is within this
// (the agreement tolerance of issue 12, item 4).
inline constexpr double kRasterAgreementTolerance = 1e-3;

struct RasterTradeoffOptions {
  int width = 0, height = 0;  // full-size image, pixels; 0: the scene's (tradeoff_image_size)
  int runs = 5;               // timed frames per setting; the median is reported
  int reference_spp = 256;    // samples per pixel of the exact reference
  std::vector<int> tessellation_levels{2, 4, 8, 16, 32};    // teapot scenes; finest: the base's
  std::vector<int> shadow_map_sizes{256, 512, 1024, 2048};  // texels per cube face side
  std::vector<float> shadow_biases{0.0f, 0.5f, 1.5f, 4.0f, 12.0f};  // RasterSettings::shadow_bias
  const std::atomic<bool>* cancel = nullptr;  // checked between frames and inside references
};

// Options that measure against the same reference as the CPU rows of `options` (size, reference
// spp, tessellation levels, runs).
RasterTradeoffOptions raster_options_like(const TradeoffOptions& options);

// What a raster frame is drawn with. tessellation 0: the scene has no teapot.
struct RasterConfig {
  int tessellation = 0;
  bool shadows = true;  // the scene's render.shadows for this frame
  RasterSettings settings;
};
bool operator==(const RasterConfig& a, const RasterConfig& b);

// One row to measure: the CPU baseline (cpu true: the engine's render() at 1 spp of the base
// scene) or a raster configuration.
struct RasterTradeoffSetting {
  std::string knob, setting;
  RasterConfig config;
  bool cpu = false;
  bool base = false;  // the raster base: per-pixel, default shadow map and bias, finest teapot
};

// Every row's setting for scene, in order: cpu "1 spp"; raster-shading pixel, vertex;
// raster-shadow-map each size, then off; raster-bias each bias; for a teapot scene
// raster-tessellation "pixel N" then "vertex N" for each level. finest: the teapot level of the
// base (0: no teapot). Throws std::invalid_argument for options out of range.
std::vector<RasterTradeoffSetting> raster_tradeoff_settings(const Scene& scene,
                                                            const RasterTradeoffOptions& options,
                                                            int finest);

struct RasterTradeoffRow {
  std::string knob;     // "cpu", "raster-shading", "raster-shadow-map", "raster-bias",
                        // "raster-tessellation"
  std::string setting;  // cpu: "1 spp"; shading: "pixel", "vertex"; shadow map: "256".."2048",
                        // "off"; bias: "1.5" (texels); tessellation: "pixel 8", "vertex 8"
  // Median milliseconds of one frame. Raster: RasterTiming::total_ms() (upload, shadow pass,
  // draw, readback of the total) of a frame after one of the same configuration, so meshes and
  // shadow maps are kept, as in a camera drag. cpu: render() at 1 spp, BVH build included, as
  // gloss-cli tradeoff times its rows.
  double time_ms = 0;
  double draw_ms = 0;    // raster: median of the draw phase alone; cpu: 0
  double shadow_ms = 0;  // raster: median shadow pass of a frame whose light moved (what a light
                         // drag adds to time_ms); 0 when shadows are off
  ImageMetrics error;    // total image against the exact reference, every pixel
  // % of pixels whose total is within kRasterAgreementTolerance on every channel of
  // render_reference<double> at 1 spp of the row's scene (its teapot level, shadows as the scene
  // says, per-pixel): the share the raster agreement tests are about.
  double pct_agree = 0;
  bool base_setting = false;
};

// CSV: gloss-cli tradeoff's columns (knob,setting,time_ms,rmse,psnr_db,max_abs,pct_pixels_off),
// then draw_ms,shadow_ms,pct_within_1e-3_of_1spp (empty draw and shadow cells for the cpu row).
std::string raster_tradeoff_to_csv(const std::vector<RasterTradeoffRow>& rows);
// The rows as a fixed-width table, a header line first (stdout of scripts, docs).
std::string raster_tradeoff_table(const std::vector<RasterTradeoffRow>& rows);

}  // namespace gloss
