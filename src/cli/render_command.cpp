// gloss-cli render SCENE.json|SHOT.png [-o OUT.png] [--pfm OUT.pfm] [--exr OUT.exr] [--terms DIR]
//                  [--width N] [--height N] [--spp N] [--model phong|blinn-phong]
//                  [--shadows on|off] [--srgb] [--exposure STOPS] [--tone none|reinhard|aces]
//                  [--sampling adaptive|uniform] [--aa-threshold T] [--precision float|double]
//                  [--physical]
// Options override the scene's render block; the result is validated again before rendering.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <unistd.h>

#include "base/assets.h"
#include "base/error.h"
#include "base/text/ascii.h"
#include "base/text/number_text.h"
#include "base/text/text_distance.h"
#include "base/version.h"
#include "cli/commands.h"
#include "cli/scene_messages.h"
#include "engine/renderer.h"
#include "io/image/exr_writer.h"
#include "io/image/image_io.h"
#include "io/image/scene_in_png.h"
#include "io/scene/scene_loader.h"
#include "reference/reference_renderer.h"

namespace gloss {

namespace {

namespace fs = std::filesystem;

struct RenderArgs {
  std::string scene;
  std::string png, pfm, exr, terms_dir;
  long long width = 0, height = 0, spp = 0;
  std::string model, shadows, sampling, tone;
  double aa_threshold = 0, exposure = 0;
  std::string precision = "float";  // float: the fast renderer; double: the reference path
  bool srgb = false;
  bool physical = false;  // materials with a `reference` shaded by it (double path)
  CLI::Option* precision_option = nullptr;
  CLI::Option *png_option = nullptr, *pfm_option = nullptr, *exr_option = nullptr;
  CLI::Option* terms_option = nullptr;
  CLI::Option *width_option = nullptr, *height_option = nullptr, *spp_option = nullptr;
  CLI::Option *model_option = nullptr, *shadows_option = nullptr;
  CLI::Option *sampling_option = nullptr, *aa_threshold_option = nullptr;
  CLI::Option *exposure_option = nullptr, *tone_option = nullptr;
};

// A size option's value, refused before it reaches the scene (and before any allocation).
int checked_option(const RenderArgs& args, const std::string& option, long long value,
                   long long hi) {
  if (value < 1 || value > hi) {
    throw InputError(
        args.scene,
        "must be a whole number from 1 to " + std::to_string(hi) + ", got " + std::to_string(value),
        0, 0, option);
  }
  return static_cast<int>(value);
}

void apply_overrides(const RenderArgs& args, Scene& scene) {
  RenderSettings& render = scene.render;
  if (*args.width_option) render.width = checked_option(args, "--width", args.width, kMaxImageSide);
  if (*args.height_option) {
    render.height = checked_option(args, "--height", args.height, kMaxImageSide);
  }
  if (*args.spp_option) render.spp = checked_option(args, "--spp", args.spp, kMaxSpp);
  if (*args.model_option && !parse_shading_model(args.model, render.model)) {
    throw InputError(args.scene,
                     "unknown shading model '" + args.model + "' (did you mean '" +
                         nearest_words(args.model, {"phong", "blinn-phong"}, 1).front() + "'?)",
                     0, 0, "--model");
  }
  if (*args.shadows_option) {
    if (args.shadows != "on" && args.shadows != "off") {
      throw InputError(args.scene, "expected 'on' or 'off', got '" + args.shadows + "'", 0, 0,
                       "--shadows");
    }
    render.shadows = args.shadows == "on";
  }
  if (*args.sampling_option && !parse_sampling(args.sampling, render.sampling)) {
    throw InputError(args.scene, "expected 'adaptive' or 'uniform', got '" + args.sampling + "'", 0,
                     0, "--sampling");
  }
  if (*args.aa_threshold_option) {
    if (!(args.aa_threshold >= 0.0 && args.aa_threshold <= 1.0)) {
      throw InputError(args.scene, "must be a number from 0 to 1", 0, 0, "--aa-threshold");
    }
    render.aa_threshold = static_cast<float>(args.aa_threshold);
  }
  if (args.srgb) render.srgb = true;
  if (*args.exposure_option) {
    if (!(std::abs(args.exposure) <= kMaxExposureStops)) {
      throw InputError(args.scene, "must be a number of stops from -32 to 32", 0, 0, "--exposure");
    }
    render.exposure = static_cast<float>(args.exposure);
  }
  if (*args.tone_option && !parse_tone_curve(args.tone, render.tone)) {
    throw InputError(args.scene,
                     "unknown tone curve '" + args.tone + "' (did you mean '" +
                         nearest_words(args.tone, {"none", "reinhard", "aces"}, 1).front() + "'?)",
                     0, 0, "--tone");
  }
  if (args.precision != "float" && args.precision != "double") {
    throw InputError(args.scene, "expected 'float' or 'double', got '" + args.precision + "'", 0, 0,
                     "--precision");
  }
  if (args.physical && *args.precision_option && args.precision != "double") {
    throw InputError(args.scene, "--physical renders on the double-precision path", 0, 0,
                     "--precision");
  }
  validate_scene(scene);
}

// Refuses an output folder that is missing or cannot take a new file, before the render runs.
void check_writable_folder(const fs::path& folder, const std::string& output) {
  const fs::path dir = folder.empty() ? fs::path(".") : folder;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) {
    throw RuntimeFailure("cannot write " + output + ": folder " + dir.string() + " does not exist");
  }
  const fs::path probe = dir / (".gloss-cli-probe-" + std::to_string(::getpid()));
  { std::ofstream(probe.string(), std::ios::binary); }
  if (!fs::exists(probe, ec)) {
    throw RuntimeFailure("cannot write " + output + ": folder " + dir.string() +
                         " is not writable");
  }
  fs::remove(probe, ec);
}

// The settings line of the output and of the PNGs' gloss:settings chunk; it names the display
// transform the PNGs went through (PFM and EXR hold the linear image before it).
std::string settings_summary(const RenderSettings& r, const std::string& precision) {
  return std::to_string(r.width) + "x" + std::to_string(r.height) + ", " + std::to_string(r.spp) +
         " spp, " + to_string(r.model) + ", shadows " + (r.shadows ? "on" : "off") +
         ", energy_normalize " + (r.energy_normalize ? "on" : "off") + ", srgb " +
         (r.srgb ? "on" : "off") + ", exposure " + number_text(r.exposure) + ", tone " +
         to_string(r.tone) + ", pow " + (r.pow == PowMode::exact ? "exact" : "fast") + ", seed " +
         std::to_string(r.seed) + ", precision " + precision +
         (r.spp > 1 ? std::string(", sampling ") + to_string(r.sampling) : std::string());
}

// Writes every requested file; if one fails, the ones already written by this run are removed
// so that a failure leaves no output behind.
class OutputWriter {
 public:
  OutputWriter(const Scene& scene, const std::string& precision)
      : m_display(display_transform(scene.render)) {
    m_text = {{"Software", std::string("gloss ") + gloss_version()},
              {kSceneChunkKeyword, embedded_scene_text(scene)},
              {"gloss:settings", settings_summary(scene.render, precision)}};
  }
  ~OutputWriter() {
    if (m_committed) return;
    std::error_code ec;
    for (const std::string& path : m_written) fs::remove(path, ec);
  }
  void png(const std::string& path, const Image& image) {
    write_png(path, image, m_display, m_text);
    m_written.push_back(path);
  }
  void pfm(const std::string& path, const Image& image) {
    write_pfm(path, image);
    m_written.push_back(path);
  }
  void exr(const std::string& path, const Image& image) {
    write_exr(path, image);
    m_written.push_back(path);
  }
  const std::vector<std::string>& commit() {
    m_committed = true;
    return m_written;
  }

 private:
  DisplayTransform m_display;  // the PNGs'
  TextChunks m_text;
  std::vector<std::string> m_written;
  bool m_committed = false;
};

// Each output is written in its option's format whatever its name says; a name whose extension
// says another (PNG bytes in shot.jpg) is refused before anything is rendered.
void check_extension(const std::string& path, const char* option, const char* extension,
                     const char* format) {
  if (path.empty() || lower_extension(path) == extension) return;
  throw InputError(path,
                   std::string(option) + " writes " + format + ": name the file *" + extension);
}

void run_render(RenderArgs args) {
  check_extension(args.png, "-o", ".png", "PNG");
  check_extension(args.pfm, "--pfm", ".pfm", "PFM");
  check_extension(args.exr, "--exr", ".exr", "OpenEXR");
  std::vector<std::string> warnings, notes;
  Scene scene = load_scene(args.scene, &warnings, &notes);
  apply_overrides(args, scene);
  if (args.physical) args.precision = "double";

  if (!*args.png_option && !*args.pfm_option && !*args.exr_option && !*args.terms_option) {
    // In the current folder; a PNG given as the scene is not overwritten by its own re-render.
    const bool from_png = has_png_signature(args.scene);
    args.png = fs::path(args.scene).stem().string() + (from_png ? "-rerender.png" : ".png");
  }
  if (!args.png.empty()) check_writable_folder(fs::path(args.png).parent_path(), args.png);
  if (!args.pfm.empty()) check_writable_folder(fs::path(args.pfm).parent_path(), args.pfm);
  if (!args.exr.empty()) check_writable_folder(fs::path(args.exr).parent_path(), args.exr);
  if (!args.terms_dir.empty()) {
    std::error_code ec;
    fs::create_directories(args.terms_dir, ec);
    if (ec) throw RuntimeFailure("cannot create folder " + args.terms_dir + ": " + ec.message());
    check_writable_folder(args.terms_dir, args.terms_dir);
  }

  RenderOptions options;
  options.terms = !args.terms_dir.empty();
  const auto start = std::chrono::steady_clock::now();
  TermImages images;
  std::vector<std::uint32_t> refined;  // adaptive sampling's refined pixels
  const bool adaptive = scene.render.spp > 1 && scene.render.sampling == Sampling::adaptive;
  if (args.precision == "double") {
    // Adaptive sampling: the fast renderer's placement, then every sample in double.
    std::vector<std::uint8_t> mask;
    ReferenceOptions reference;
    reference.physical = args.physical;
    if (adaptive) {
      options.terms = false;
      options.refined = &refined;
      render(scene, options);
      mask.assign(static_cast<std::size_t>(scene.render.width) * scene.render.height, 0);
      for (const std::uint32_t p : refined) mask[p] = 1;
      reference.refined = &mask;
    }
    images = render_reference<double>(scene, reference);
  } else {
    options.refined = &refined;
    images = render(scene, options);
  }
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();

  const std::string precision = args.physical ? "double, physical reference" : args.precision;
  OutputWriter writer(scene, precision);
  if (!args.png.empty()) writer.png(args.png, images.total);
  if (!args.pfm.empty()) writer.pfm(args.pfm, images.total);
  if (!args.exr.empty()) writer.exr(args.exr, images.total);
  if (!args.terms_dir.empty()) {
    for (Term term : {Term::emissive, Term::ambient, Term::diffuse, Term::specular, Term::total}) {
      const fs::path base = fs::path(args.terms_dir) / to_string(term);
      writer.pfm(base.string() + ".pfm", term_image(images, term));
      writer.png(base.string() + ".png", term_image(images, term));
    }
  }

  char time_text[64];
  std::snprintf(time_text, sizeof time_text, "%.1f ms", ms);
  std::cout << "rendered " << args.scene << " (" << settings_summary(scene.render, precision)
            << ") in " << time_text;
  if (adaptive) {
    char share[64];
    std::snprintf(share, sizeof share, "; refined %.1f%% of the pixels",
                  100.0 * static_cast<double>(refined.size()) /
                      (static_cast<double>(scene.render.width) * scene.render.height));
    std::cout << share;
  }
  std::cout << "\n";
  for (const std::string& path : writer.commit()) std::cout << "wrote " << path << "\n";
  print_scene_messages(notes, warnings);
}

}  // namespace

void add_render_command(CLI::App& app) {
  CLI::App* sub = app.add_subcommand("render", "Render a scene file to PNG / PFM images");
  auto args = std::make_shared<RenderArgs>();
  sub->add_option("scene", args->scene,
                  "Scene file (JSON, " + doc_path("scene-format.md") +
                      "), or a PNG written by gloss (its embedded scene)")
      ->required();
  args->png_option = sub->add_option(
      "-o,--output", args->png,
      "PNG output (8-bit, through the display transform: exposure, tone, clamp, encoding); "
      "default <scene stem>.png (<stem>-rerender.png for a PNG scene) when no output is given");
  args->pfm_option = sub->add_option("--pfm", args->pfm, "PFM output (linear float, unclamped)");
  args->exr_option = sub->add_option(
      "--exr", args->exr, "OpenEXR output (linear 32-bit float, unclamped, ZIP-compressed)");
  args->terms_option = sub->add_option(
      "--terms", args->terms_dir,
      "Folder for emissive/ambient/diffuse/specular/total as .pfm and .png (created)");
  args->width_option = sub->add_option("--width", args->width, "Image width in pixels");
  args->height_option = sub->add_option("--height", args->height, "Image height in pixels");
  args->spp_option = sub->add_option("--spp", args->spp, "Samples per pixel");
  args->model_option = sub->add_option("--model", args->model, "phong or blinn-phong");
  args->shadows_option = sub->add_option("--shadows", args->shadows, "on or off");
  args->sampling_option = sub->add_option(
      "--sampling", args->sampling,
      "spp > 1: adaptive (default: samples where the centre image has edges) or uniform");
  args->aa_threshold_option = sub->add_option(
      "--aa-threshold", args->aa_threshold,
      "adaptive: refine where the centre image curves by more than T / 10 (its Laplacian, "
      "0..1, default 1/64)");
  sub->add_flag("--srgb", args->srgb, "sRGB-encode the PNGs (default: clamp only)");
  args->exposure_option = sub->add_option(
      "--exposure", args->exposure,
      "the PNGs' exposure in stops (-32..32): displayed = linear x 2^STOPS (render.exposure)");
  args->tone_option = sub->add_option(
      "--tone", args->tone,
      "the PNGs' tone curve after the exposure: none (default), reinhard or aces (render.tone)");
  args->precision_option = sub->add_option(
      "--precision", args->precision,
      "float (default: the fast renderer) or double (the reference path, docs/accuracy.md)");
  sub->add_flag("--physical", args->physical,
                "Shade materials that have a physical `reference` by it (GGX, "
                "docs/spec/physical-reference.md) on the double path; others stay Phong");
  sub->callback([args] { run_render(*args); });
}

}  // namespace gloss
