#include "analysis/tradeoff/tradeoff.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>
#include <tuple>

#include "analysis/image/image_resample.h"
#include "base/timing.h"
#include "engine/renderer.h"
#include "io/scene/scene_loader.h"
#include "reference/reference_renderer.h"

namespace gloss {

namespace {

using Clock = std::chrono::steady_clock;

// Which renderer a configuration goes through.
enum class Path { fast, reference_double, gouraud_float };

// One point of the knob space. tessellation 0: the scene has no teapot.
struct Config {
  int spp = 1;
  float aa_threshold = -1;  // adaptive sampling's threshold; < 0: uniform sampling
  int tessellation = 0;
  PowMode pow = PowMode::exact;
  Path path = Path::fast;
  int divisor = 1;
  bool shadows = true;
  int env_samples = 0, env_resolution = 2;  // the environment's knobs (render_settings.h)
  MapFilter map_filter = MapFilter::trilinear;
  int map_divisor = 1;  // maps at 1/map_divisor of their size

  bool operator<(const Config& o) const {
    return std::tie(spp, aa_threshold, tessellation, pow, path, divisor, shadows, env_samples,
                    env_resolution, map_filter, map_divisor) <
           std::tie(o.spp, o.aa_threshold, o.tessellation, o.pow, o.path, o.divisor, o.shadows,
                    o.env_samples, o.env_resolution, o.map_filter, o.map_divisor);
  }
  bool operator==(const Config& o) const { return !(*this < o) && !(o < *this); }
};

struct Measurement {
  double time_ms = 0;
  ImageMetrics error;
};

std::string divisor_name(int d) {
  return d == 1 ? "1" : "1/" + std::to_string(d);
}

void check_options(const TradeoffOptions& o) {
  auto spp_ok = [](int s) { return s >= 1 && s <= kMaxSpp; };
  if (o.runs < 1) throw std::invalid_argument("tradeoff: runs must be at least 1");
  if (!spp_ok(o.reference_spp) || !spp_ok(o.base_spp) ||
      !std::all_of(o.spp_levels.begin(), o.spp_levels.end(), spp_ok)) {
    throw std::invalid_argument("tradeoff: samples per pixel must be 1.." +
                                std::to_string(kMaxSpp));
  }
  if (o.width < 0 || o.height < 0 || o.width > kMaxImageSide || o.height > kMaxImageSide) {
    throw std::invalid_argument("tradeoff: image size out of range");
  }
  for (int level : o.tessellation_levels) {
    if (level < 1 || level > 64) throw std::invalid_argument("tradeoff: tessellation is 1..64");
  }
  for (int d : o.resolution_divisors) {
    if (d < 1) throw std::invalid_argument("tradeoff: resolution divisors must be >= 1");
  }
  for (int n : o.env_sample_levels) {
    if (n < 0 || n > 65536) throw std::invalid_argument("tradeoff: env_samples is 0..65536");
  }
  for (int r : o.env_resolution_levels) {
    if (r < 1 || r > 16) throw std::invalid_argument("tradeoff: env_resolution is 1..16");
  }
  for (int d : o.map_divisors) {
    if (d < 1 || (d & (d - 1)) != 0) {
      throw std::invalid_argument("tradeoff: map divisors must be powers of 2");
    }
  }
}

// Everything one run_tradeoff call shares: the scenes per tessellation, the reference image and
// the errors already computed (rows of different knobs can name the same configuration).
class Session {
 public:
  Session(const Scene& scene, const TradeoffOptions& options) : m_options(options) {
    tradeoff_image_size(scene, options, m_width, m_height);
    if (has_object_type(scene, ObjectType::teapot) && !options.tessellation_levels.empty()) {
      m_finest =
          *std::max_element(options.tessellation_levels.begin(), options.tessellation_levels.end());
    }
    m_scenes.emplace(m_finest, m_finest > 0 ? with_teapot_tessellation(scene, m_finest) : scene);
    m_base.spp = options.base_spp;
    m_base.tessellation = m_finest;
    m_base.shadows = scene.render.shadows;
    m_base.env_samples = scene.render.env_samples;
    m_base.env_resolution = scene.render.env_resolution;
    m_environment = scene.environment.present();
    Scene& full = m_scenes.at(m_finest);
    full.render.width = m_width;
    full.render.height = m_height;
    validate_scene(full);
  }

  bool cancelled() const {
    return m_options.cancel != nullptr && m_options.cancel->load(std::memory_order_relaxed);
  }

  // The reference image; false when cancelled while it was being computed.
  bool make_reference() {
    Config ref = m_base;
    ref.spp = m_options.reference_spp;
    ref.path = Path::reference_double;
    m_reference = render_config(ref);
    return !cancelled();
  }

  // Median times and errors of one knob's configurations, measured together: round r renders
  // every distinct configuration once, starting one further along each round, so that a change
  // of machine load (other processes on the cores) falls on all of them alike and the knob's
  // settings compare fairly. Images are deterministic: each configuration's error is computed
  // once. false when cancelled.
  bool measure_knob(const std::vector<Config>& configs, std::vector<Measurement>& out) {
    std::vector<Config> distinct;
    for (const Config& c : configs) {
      if (std::find(distinct.begin(), distinct.end(), c) == distinct.end()) distinct.push_back(c);
    }
    const std::size_t n = distinct.size();
    std::vector<std::vector<double>> times(n);
    for (int run = 0; run < m_options.runs; ++run) {
      for (std::size_t k = 0; k < n; ++k) {
        const std::size_t i = (k + static_cast<std::size_t>(run)) % n;
        if (cancelled()) return false;
        const Clock::time_point start = Clock::now();
        const Image image = render_config(distinct[i]);
        times[i].push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
        if (m_errors.find(distinct[i]) == m_errors.end()) {
          m_errors.emplace(distinct[i], compare_images(image, m_reference));
        }
      }
    }
    if (cancelled()) return false;
    out.clear();
    for (const Config& c : configs) {
      const std::size_t i = static_cast<std::size_t>(
          std::find(distinct.begin(), distinct.end(), c) - distinct.begin());
      out.push_back({median(times[i]), m_errors.at(c)});
    }
    return true;
  }

  int finest() const { return m_finest; }
  bool environment() const { return m_environment; }
  bool textured() const {
    for (const Material& m : m_scenes.at(m_finest).materials) {
      if (m.textured()) return true;
    }
    return false;
  }
  // The configuration every row changes one knob of.
  const Config& base() const { return m_base; }

 private:
  const Scene& scene_for(int tessellation) {
    auto it = m_scenes.find(tessellation);
    if (it == m_scenes.end()) {
      Scene s = with_teapot_tessellation(m_scenes.at(m_finest), tessellation);
      it = m_scenes.emplace(tessellation, std::move(s)).first;
    }
    return it->second;
  }

  // The scene of c's tessellation with its maps at 1/map_divisor of their size: each pyramid
  // from the level of that size (made once, shared by the rows).
  const Scene& scene_for(const Config& c) {
    if (c.map_divisor == 1) return scene_for(c.tessellation);
    const auto key = std::make_pair(c.tessellation, c.map_divisor);
    auto it = m_map_scenes.find(key);
    if (it == m_map_scenes.end()) {
      Scene s = scene_for(c.tessellation);
      int drop = 0;
      while ((1 << drop) < c.map_divisor) ++drop;
      for (Material& m : s.materials) {
        for (int i = 0; i < kMapSlots; ++i) {
          TextureMap& map = m.map(static_cast<MapSlot>(i));
          if (!map.present() || map.texture->level_count() <= 1) continue;
          auto smaller = std::make_shared<Texture>(*map.texture);
          const int from = std::min(drop, smaller->level_count() - 1);
          smaller->levels.erase(smaller->levels.begin(), smaller->levels.begin() + from);
          map.texture = std::move(smaller);
        }
      }
      it = m_map_scenes.emplace(key, std::move(s)).first;
    }
    return it->second;
  }

  // One render of c at full size (reduced sizes are upsampled), total image only.
  Image render_config(const Config& c) {
    Scene s = scene_for(c);
    s.render.map_filter = c.map_filter;
    s.render.width = std::max(1, (m_width + c.divisor / 2) / c.divisor);
    s.render.height = std::max(1, (m_height + c.divisor / 2) / c.divisor);
    s.render.spp = c.spp;
    s.render.sampling = c.aa_threshold < 0 ? Sampling::uniform : Sampling::adaptive;
    s.render.aa_threshold = std::max(0.0f, c.aa_threshold);
    s.render.pow = c.pow;
    s.render.shadows = c.shadows;
    s.render.env_samples = c.env_samples;
    s.render.env_resolution = c.env_resolution;
    Image image;
    if (c.path == Path::fast) {
      RenderOptions options;
      options.terms = false;
      image = render(s, options).total;
    } else {
      ReferenceOptions options;
      options.cancel = m_options.cancel;
      options.gouraud = c.path == Path::gouraud_float;
      image = c.path == Path::reference_double ? render_reference<double>(s, options).total
                                               : render_reference<float>(s, options).total;
    }
    return c.divisor > 1 ? resize_bilinear(image, m_width, m_height) : image;
  }

  const TradeoffOptions& m_options;
  int m_width = 0, m_height = 0;
  int m_finest = 0;  // 0: no teapot
  bool m_environment = false;
  Config m_base;
  std::map<int, Scene> m_scenes;
  std::map<std::pair<int, int>, Scene> m_map_scenes;  // (tessellation, map divisor)
  Image m_reference;
  std::map<Config, ImageMetrics> m_errors;
};

struct Setting {
  std::string name;
  Config config;
  bool reference = false;
};

// The settings of one knob, each as a change of the base configuration.
std::vector<Setting> settings_of(Knob knob, const Session& session, const TradeoffOptions& o) {
  const Config base = session.base();
  std::vector<Setting> out;
  auto add = [&](std::string name, auto change, bool reference) {
    Config c = base;
    change(c);
    out.push_back({std::move(name), c, reference});
  };
  if (knob == Knob::spp) {
    for (int s : o.spp_levels) {
      add(
          std::to_string(s), [s](Config& c) { c.spp = s; }, s == o.reference_spp);
    }
  } else if (knob == Knob::adaptive) {
    add(
        "uniform", [](Config&) {}, false);  // the base: what adaptive sampling is weighed against
    for (float t : o.adaptive_thresholds) {
      add(
          std::to_string(o.adaptive_spp) + " t=1/" + std::to_string(std::lround(1.0f / t)),
          [&o, t](Config& c) {
            c.spp = o.adaptive_spp;
            c.aa_threshold = t;
          },
          false);
    }
  } else if (knob == Knob::tessellation) {
    if (session.finest() == 0) return out;  // no teapot: skipped (tradeoff_notes says so)
    for (int level : o.tessellation_levels) {
      add(
          std::to_string(level), [level](Config& c) { c.tessellation = level; },
          level == session.finest());
    }
  } else if (knob == Knob::pow) {
    add(
        "exact", [](Config&) {}, true);
    add(
        "fast", [](Config& c) { c.pow = PowMode::fast; }, false);
  } else if (knob == Knob::precision) {
    add(
        "float", [](Config&) {}, false);
    add(
        "double", [](Config& c) { c.path = Path::reference_double; }, true);
  } else if (knob == Knob::shading) {
    add(
        "per-pixel", [](Config&) {}, true);
    add(
        "gouraud", [](Config& c) { c.path = Path::gouraud_float; }, false);
  } else if (knob == Knob::resolution) {
    for (int d : o.resolution_divisors) {
      add(
          divisor_name(d), [d](Config& c) { c.divisor = d; }, d == 1);
    }
  } else if (knob == Knob::shadows) {
    add(
        "on", [](Config& c) { c.shadows = true; }, base.shadows);
    add(
        "off", [](Config& c) { c.shadows = false; }, !base.shadows);
  } else if (knob == Knob::env_samples) {
    if (!session.environment()) return out;  // tradeoff_notes says so
    for (int n : o.env_sample_levels) {
      add(
          n == 0 ? "0 (fast)" : std::to_string(n), [n](Config& c) { c.env_samples = n; }, false);
    }
  } else if (knob == Knob::env_resolution) {
    if (!session.environment()) return out;
    for (int r : o.env_resolution_levels) {
      add(
          std::to_string(r),
          [r](Config& c) {
            c.env_samples = 0;
            c.env_resolution = r;
          },
          false);
    }
  } else if (knob == Knob::map_filter) {
    if (!session.textured()) return out;  // tradeoff_notes says so
    add(
        "nearest", [](Config& c) { c.map_filter = MapFilter::nearest; }, false);
    add(
        "bilinear", [](Config& c) { c.map_filter = MapFilter::bilinear; }, false);
    add(
        "trilinear", [](Config&) {}, true);
  } else if (knob == Knob::map_resolution) {
    if (!session.textured()) return out;
    for (int d : o.map_divisors) {
      add(
          divisor_name(d), [d](Config& c) { c.map_divisor = d; }, d == 1);
    }
  }
  return out;
}

}  // namespace

std::vector<TradeoffRow> run_tradeoff(const Scene& scene, const TradeoffOptions& options,
                                      const std::function<bool(const TradeoffRow&)>& on_row) {
  check_options(options);
  Session session(scene, options);
  std::vector<TradeoffRow> rows;
  if (!session.make_reference()) return rows;
  for (const Knob knob : tradeoff_knobs()) {
    if (!options.knobs.empty() &&
        std::find(options.knobs.begin(), options.knobs.end(), knob) == options.knobs.end()) {
      continue;
    }
    const std::vector<Setting> settings = settings_of(knob, session, options);
    std::vector<Config> configs;
    for (const Setting& setting : settings) configs.push_back(setting.config);
    std::vector<Measurement> measured;
    if (!session.measure_knob(configs, measured)) return rows;
    for (std::size_t i = 0; i < settings.size(); ++i) {
      TradeoffRow row;
      row.knob = knob;
      row.setting = settings[i].name;
      row.time_ms = measured[i].time_ms;
      row.error = measured[i].error;
      row.reference_setting = settings[i].reference;
      row.base_setting = settings[i].config == session.base();
      rows.push_back(row);
      if (on_row && !on_row(rows.back())) return rows;
    }
  }
  return rows;
}

std::string tradeoff_to_csv(const std::vector<TradeoffRow>& rows) {
  std::string csv = "knob,setting,time_ms,rmse,psnr_db,max_abs,pct_pixels_off\n";
  char line[256];
  for (const TradeoffRow& r : rows) {
    std::snprintf(line, sizeof line, "%s,%s,%.3f,%.6g,%s,%.6g,%.4f\n", to_string(r.knob),
                  r.setting.c_str(), r.time_ms, r.error.rmse, psnr_text(r.error.psnr_db).c_str(),
                  r.error.max_abs, r.error.pct_pixels_off);
    csv += line;
  }
  return csv;
}

}  // namespace gloss
