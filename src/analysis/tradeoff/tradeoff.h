#pragma once
// Speed against accuracy, measured: every setting of every accuracy knob rendered, timed (median
// of several runs) and compared with a reference (double precision, reference_spp samples, exact
// pow, finest teapot tessellation, per-pixel shading, full size, shadows as the scene says).
// The base of every row is that reference configuration rendered by the fast float renderer at
// base_spp; each row changes one knob of the base, so a row's error is the base's error plus what
// its knob costs. Usable from a worker thread: cancel with the flag or by returning false from
// on_row.
#include <atomic>
#include <functional>
#include <string>
#include <vector>

#include "analysis/image/image_metrics.h"
#include "scene/scene.h"

namespace gloss {

// The accuracy knobs, in the order run_tradeoff measures them.
// env_samples (directions per sample towards the environment's exact terms, 0: the fast path)
// and env_resolution (the fast path's texels per lobe width, measured with env_samples 0) only
// for a scene with an environment light; shadows is its visibility on or off too. map_filter and
// map_resolution only for a scene with maps.
enum class Knob {
  spp,
  adaptive,
  tessellation,
  pow,
  precision,
  shading,
  resolution,
  shadows,
  env_samples,
  env_resolution,
  map_filter,      // how maps are read: nearest, bilinear at level 0, trilinear (the contract)
  map_resolution,  // every map at 1/2^k of its size (its pyramid from level k)
};

// Every knob, in measuring order.
const std::vector<Knob>& tradeoff_knobs();
// The knob's name as tables, CSV files and the Quality window print it ("spp", "pow" ...);
// parse_knob returns false for any other name.
const char* to_string(Knob knob);
bool parse_knob(const std::string& name, Knob& knob);

struct TradeoffOptions {
  int width = 0, height = 0;  // full-size image, pixels; 0: the scene's (one 0: from its aspect)
  int runs = 5;               // timed renders per row; the median is reported
  int reference_spp = 256;    // samples per pixel of the reference
  int base_spp = 4;           // samples per pixel of every row whose knob is not spp
  std::vector<int> spp_levels{1, 2, 4, 8, 16, 32, 64};  // spp knob, uniform sampling
  int adaptive_spp = 16;                                // adaptive knob: its spp and
  std::vector<float> adaptive_thresholds{1.0f / 16, 1.0f / 32, 1.0f / 64, 1.0f / 128,
                                         1.0f / 256};        // refine thresholds
  std::vector<int> tessellation_levels{2, 4, 8, 16, 32};     // teapot segments per patch side
  std::vector<int> resolution_divisors{8, 4, 2, 1};          // preview at 1/d, upsampled
  std::vector<int> env_sample_levels{0, 16, 64, 256, 1024};  // env_samples (0: fast path)
  std::vector<int> env_resolution_levels{1, 2, 4};           // env_resolution knob
  std::vector<int> map_divisors{8, 4, 2, 1};                 // maps at 1/d (a power of 2)
  std::vector<Knob> knobs;                                   // the knobs to measure; empty: all
  const std::atomic<bool>* cancel = nullptr;  // checked between renders and inside references
};

// The full image size options give for scene: width and height, either taken from the scene's
// render block when 0 (one 0: from the scene's aspect, rounded, at least 1).
void tradeoff_image_size(const Scene& scene, const TradeoffOptions& options, int& width,
                         int& height);

// Settings for a quick look from the editor's Quality panel: 256 pixels wide, 3 runs, a 64-spp
// reference, spp up to 16, adaptive at thresholds 1/16 and 1/64. A few seconds on the shipped
// scenes.
TradeoffOptions quick_tradeoff_options();

struct TradeoffRow {
  Knob knob = Knob::spp;
  std::string setting;  // spp: "1".."64"; adaptive: "uniform" (the base), "16 t=1/64" (spp and
                        // refine threshold); tessellation: "2".."32"; pow: "exact", "fast";
                        // precision: "float", "double"; shading: "per-pixel", "gouraud";
                        // resolution: "1/8".."1"; shadows: "on", "off"; env_samples:
                        // "0 (fast)", "16".."256"; env_resolution: "1".."4"; map_filter:
                        // "nearest", "bilinear", "trilinear"; map_resolution: "1/8".."1"
  double time_ms = 0;   // median wall time of one render: BVH build, trace, shade (resolution:
                        // the reduced render plus the bilinear upsampling to full size); the
                        // base's own time differs a little from knob to knob (timed with each)
  ImageMetrics error;   // total image against the reference, every pixel
  bool reference_setting = false;  // the reference's own setting of this knob
  bool base_setting = false;       // the base's setting: the row renders the base configuration
};

// What the rows cannot say by themselves about this scene (a skipped knob, what gouraud touches,
// where times come from); one line each, for the table and the panel.
std::vector<std::string> tradeoff_notes(const Scene& scene, const TradeoffOptions& options);

// Measures the knobs of options.knobs for scene and returns the rows in order. A knob's settings
// are timed together, round-robin (run r renders each setting once), so that load from other
// processes falls on them alike; the rows of a knob arrive together once it is measured, each
// passed to on_row (may be empty). Returning false from on_row stops early with the rows so far,
// and so does options.cancel (checked between renders and inside reference renders). Throws
// InputError for a scene that cannot be rendered, std::invalid_argument for options out of range
// (runs < 1, spp outside 1..kMaxSpp, unknown knob, tessellation outside 1..64, divisor < 1).
std::vector<TradeoffRow> run_tradeoff(
    const Scene& scene, const TradeoffOptions& options,
    const std::function<bool(const TradeoffRow&)>& on_row = nullptr);

// CSV with the header knob,setting,time_ms,rmse,psnr_db,max_abs,pct_pixels_off ("inf" for the
// PSNR of an exact match).
std::string tradeoff_to_csv(const std::vector<TradeoffRow>& rows);

}  // namespace gloss
