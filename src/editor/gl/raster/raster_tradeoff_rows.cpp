#include "editor/gl/raster/raster_tradeoff_rows.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "base/text/number_text.h"

namespace gloss {

namespace {

void check_options(const RasterTradeoffOptions& o) {
  if (o.runs < 1) throw std::invalid_argument("raster tradeoff: runs must be at least 1");
  if (o.reference_spp < 1 || o.reference_spp > kMaxSpp) {
    throw std::invalid_argument("raster tradeoff: reference spp must be 1.." +
                                std::to_string(kMaxSpp));
  }
  if (o.width < 0 || o.height < 0 || o.width > kMaxImageSide || o.height > kMaxImageSide) {
    throw std::invalid_argument("raster tradeoff: image size out of range");
  }
  for (int level : o.tessellation_levels) {
    if (level < 1 || level > 64) {
      throw std::invalid_argument("raster tradeoff: tessellation is 1..64");
    }
  }
  for (int size : o.shadow_map_sizes) {
    if (size < kMinShadowMapSize || size > kMaxShadowMapSize) {
      throw std::invalid_argument("raster tradeoff: shadow map size is " +
                                  std::to_string(kMinShadowMapSize) + ".." +
                                  std::to_string(kMaxShadowMapSize));
    }
  }
  for (float bias : o.shadow_biases) {
    if (!(bias >= 0.0f) || !std::isfinite(bias)) {
      throw std::invalid_argument("raster tradeoff: shadow bias must be finite and >= 0");
    }
  }
}

}  // namespace

RasterTradeoffOptions raster_options_like(const TradeoffOptions& options) {
  RasterTradeoffOptions o;
  o.width = options.width;
  o.height = options.height;
  o.runs = options.runs;
  o.reference_spp = options.reference_spp;
  o.tessellation_levels = options.tessellation_levels;
  return o;
}

bool operator==(const RasterConfig& a, const RasterConfig& b) {
  return a.tessellation == b.tessellation && a.shadows == b.shadows && a.settings == b.settings;
}

std::vector<RasterTradeoffSetting> raster_tradeoff_settings(const Scene& scene,
                                                            const RasterTradeoffOptions& options,
                                                            int finest) {
  check_options(options);
  RasterConfig base;
  base.tessellation = finest;
  base.shadows = scene.render.shadows;
  std::vector<RasterTradeoffSetting> out;
  auto add = [&](const char* knob, std::string setting, auto change) {
    RasterTradeoffSetting s;
    s.knob = knob;
    s.setting = std::move(setting);
    s.config = base;
    change(s.config);
    s.base = s.config == base;
    out.push_back(std::move(s));
  };
  RasterTradeoffSetting cpu;
  cpu.knob = "cpu";
  cpu.setting = "1 spp";
  cpu.config = base;
  cpu.cpu = true;
  out.push_back(cpu);
  for (const ShadingFrequency f : {ShadingFrequency::pixel, ShadingFrequency::vertex}) {
    add("raster-shading", to_string(f), [f](RasterConfig& c) { c.settings.shading = f; });
  }
  // The scene's shadows stay as it says: in a scene without shadows every size draws the same
  // image as "off".
  for (int size : options.shadow_map_sizes) {
    add("raster-shadow-map", std::to_string(size),
        [size](RasterConfig& c) { c.settings.shadow_map_size = size; });
  }
  add("raster-shadow-map", "off", [](RasterConfig& c) { c.shadows = false; });
  for (float bias : options.shadow_biases) {
    add("raster-bias", number_text(bias),
        [bias](RasterConfig& c) { c.settings.shadow_bias = bias; });
  }
  if (finest > 0) {
    for (const ShadingFrequency f : {ShadingFrequency::pixel, ShadingFrequency::vertex}) {
      for (int level : options.tessellation_levels) {
        add("raster-tessellation", std::string(to_string(f)) + " " + std::to_string(level),
            [f, level](RasterConfig& c) {
              c.settings.shading = f;
              c.tessellation = level;
            });
      }
    }
  }
  return out;
}

std::string raster_tradeoff_to_csv(const std::vector<RasterTradeoffRow>& rows) {
  std::string csv =
      "knob,setting,time_ms,rmse,psnr_db,max_abs,pct_pixels_off,draw_ms,shadow_ms,"
      "pct_within_1e-3_of_1spp\n";
  char line[320];
  for (const RasterTradeoffRow& r : rows) {
    char phases[64] = ",";
    if (r.knob != "cpu") std::snprintf(phases, sizeof phases, "%.3f,%.3f", r.draw_ms, r.shadow_ms);
    std::snprintf(line, sizeof line, "%s,%s,%.3f,%.6g,%s,%.6g,%.4f,%s,%.4f\n", r.knob.c_str(),
                  r.setting.c_str(), r.time_ms, r.error.rmse, psnr_text(r.error.psnr_db).c_str(),
                  r.error.max_abs, r.error.pct_pixels_off, phases, r.pct_agree);
    csv += line;
  }
  return csv;
}

std::string raster_tradeoff_table(const std::vector<RasterTradeoffRow>& rows) {
  char line[320];
  std::snprintf(line, sizeof line, "  %-19s %-10s %-1s %9s %8s %9s %9s %8s %9s %8s %9s\n", "knob",
                "setting", "", "time_ms", "draw_ms", "shadow_ms", "rmse", "psnr_db", "max_abs",
                "pct_off", "agree_1e-3");
  std::string table = line;
  for (const RasterTradeoffRow& r : rows) {
    char draw[32] = "-", shadow[32] = "-";
    if (r.knob != "cpu") {
      std::snprintf(draw, sizeof draw, "%.2f", r.draw_ms);
      std::snprintf(shadow, sizeof shadow, "%.2f", r.shadow_ms);
    }
    std::snprintf(line, sizeof line,
                  "  %-19s %-10s %-1s %9.2f %8s %9s %9.3g %8s %9.3g %8.3f %9.3f\n", r.knob.c_str(),
                  r.setting.c_str(), r.base_setting ? "b" : "", r.time_ms, draw, shadow,
                  r.error.rmse, psnr_text(r.error.psnr_db).c_str(), r.error.max_abs,
                  r.error.pct_pixels_off, r.pct_agree);
    table += line;
  }
  return table;
}

}  // namespace gloss
