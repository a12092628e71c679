#pragma once
// How to render: the scene's "render" block plus the accuracy knobs. Filled by the scene loader,
// overridden by gloss-cli options and edited by the editor's panels.
#include <cstdint>
#include <string>

#include "texture/texture_lookup.h"

namespace gloss {

enum class ShadingModel { phong, blinn_phong };

// "phong" / "blinn-phong" (the names of scene/fields/fields.h's render table); parse returns false
// for any other name.
const char* to_string(ShadingModel model);
bool parse_shading_model(const std::string& name, ShadingModel& model);

// How c^alpha is evaluated: exactly (std::pow semantics) or by a fast exp2/log2 approximation.
enum class PowMode { exact, fast };

// "exact" / "fast"; parse returns false for any other name.
const char* to_string(PowMode mode);
bool parse_pow_mode(const std::string& name, PowMode& mode);

// How the samples of spp > 1 are spent: every pixel gets spp stratified samples (uniform), or
// the pixel centre first and spp stratified samples only where the centre image needs them
// (adaptive; the rule is in engine/adaptive/adaptive_refinement.h and docs/spec/shading.md).
enum class Sampling { adaptive, uniform };

const char* to_string(Sampling sampling);
bool parse_sampling(const std::string& name, Sampling& sampling);

// The display transform's tone curve (docs/spec/shading.md, "Output encodings"), applied after
// the exposure and before the clamp: none (the classic look), Reinhard x / (1 + x), or
// Narkowicz's fit of the ACES film curve. The functions are display/display_transform.h's.
enum class ToneCurve { none, reinhard, aces };

// "none" / "reinhard" / "aces"; parse returns false for any other name.
const char* to_string(ToneCurve tone);
bool parse_tone_curve(const std::string& name, ToneCurve& tone);

struct RenderSettings {
  int width = 640;   // pixels
  int height = 480;  // pixels
  int spp = 1;       // samples per pixel, stratified; 1 = the pixel centre
  ShadingModel model = ShadingModel::phong;
  bool shadows = true;
  bool energy_normalize = false;     // specular x (alpha+2)/(2 pi), Blinn-Phong (alpha+8)/(8 pi)
  bool srgb = false;                 // PNG display encoding: false = clamp only (classic look)
  float exposure = 0.0f;             // display transform: stops, displayed = linear x 2^exposure
  ToneCurve tone = ToneCurve::none;  // display transform: the curve after the exposure
  std::uint32_t seed = 0;            // jitter seed for spp > 1; same seed, same image
  PowMode pow = PowMode::exact;      // accuracy knob
  Sampling sampling = Sampling::adaptive;  // for spp > 1
  // Adaptive sampling refines a pixel whose displayed total (after the display transform:
  // exposure, tone, clamp, encoding) differs from a neighbour's by more than this, per channel
  // (0..1); a speed knob: lower refines more pixels.
  float aa_threshold = 1.0f / 64.0f;
  // The environment light (docs/engine.md, "The environment"): the fast path's prefiltered maps
  // have env_resolution texels per lobe width; then env_samples directions per sample, drawn
  // from the lobes and the map and combined, converge on the contract's integrals (with
  // visibility when shadows are on). 0: the fast path alone.
  int env_resolution = 2;
  int env_samples = 64;
  // How maps are read (docs/spec/shading.md, "Textures"): trilinear at the footprint's level
  // (the contract), or a knob: bilinear or the nearest texel at level 0.
  MapFilter map_filter = MapFilter::trilinear;
};

// Largest image side and pixel count accepted; larger requests are refused before allocating.
constexpr int kMaxImageSide = 16384;
constexpr long long kMaxImagePixels = 64LL * 1024 * 1024;
constexpr int kMaxSpp = 4096;
constexpr int kMaxEnvSamples = 65536;
// Largest exposure magnitude accepted, stops: 2^32 keeps every exposed value finite in float.
constexpr float kMaxExposureStops = 32.0f;

}  // namespace gloss
