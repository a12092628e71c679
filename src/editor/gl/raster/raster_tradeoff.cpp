#include "editor/gl/raster/raster_tradeoff.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <future>
#include <map>
#include <stdexcept>
#include <thread>

#include "base/timing.h"
#include "editor/gl/raster/raster_renderer.h"
#include "engine/renderer.h"
#include "io/scene/scene_loader.h"
#include "reference/reference_renderer.h"

namespace gloss {

namespace {

using Clock = std::chrono::steady_clock;

// What the worker makes before any raster frame is drawn.
struct Prepared {
  std::map<int, Scene> scenes;      // by teapot level (0: no teapot): full size, 1 spp, exact pow
  Image reference;                  // render_reference<double> at reference_spp, finest level
  std::map<int, Image> one_sample;  // render_reference<double> at 1 spp, per level
  RasterTradeoffRow cpu;
};

// One distinct raster configuration: its frames' phases and its image's figures.
struct Measured {
  RasterConfig config;
  std::vector<double> total_ms, draw_ms, shadow_ms;
  ImageMetrics error;
  double pct_agree = 0;
  bool compared = false;
};

// World units a light moves in the frame that measures the shadow pass: any change of a light's
// position redraws the maps (shadow_maps.h), and this one is far below a pixel in the shipped
// scenes.
constexpr float kLightNudge = 1e-4f;

bool stopped(const std::atomic<bool>& cancel) {
  return cancel.load(std::memory_order_relaxed);
}

// The scenes, the references (as run_tradeoff makes its reference: the finest teapot, full size,
// uniform sampling at reference_spp, exact pow, shadows as the scene says) and the cpu row: the
// engine's render() at 1 spp of the base scene, timed runs times. Returns early when cancelled.
Prepared prepare(const Scene& input, const RasterTradeoffOptions& o, int width, int height,
                 int finest, const std::atomic<bool>& cancel) {
  Prepared p;
  Scene base = finest > 0 ? with_teapot_tessellation(input, finest) : input;
  base.render.width = width;
  base.render.height = height;
  base.render.spp = 1;
  base.render.sampling = Sampling::uniform;
  base.render.aa_threshold = 0.0f;
  base.render.pow = PowMode::exact;
  p.scenes.emplace(finest, base);
  if (finest > 0) {
    for (int level : o.tessellation_levels) {
      if (p.scenes.count(level) == 0)
        p.scenes.emplace(level, with_teapot_tessellation(base, level));
    }
  }
  ReferenceOptions exact;
  exact.cancel = &cancel;
  Scene reference_scene = base;
  reference_scene.render.spp = o.reference_spp;
  p.reference = render_reference<double>(reference_scene, exact).total;
  for (const auto& [level, scene] : p.scenes) {
    if (stopped(cancel)) return p;
    p.one_sample[level] = render_reference<double>(scene, exact).total;
  }
  RenderOptions fast;
  fast.terms = false;
  std::vector<double> times;
  Image image;
  for (int run = 0; run < o.runs && !stopped(cancel); ++run) {
    const Clock::time_point start = Clock::now();
    image = render(base, fast).total;
    times.push_back(ms_since(start));
  }
  if (stopped(cancel)) return p;
  p.cpu.knob = "cpu";
  p.cpu.setting = "1 spp";
  p.cpu.time_ms = median(times);
  p.cpu.error = compare_images(image, p.reference);
  p.cpu.pct_agree = percent_within(image, p.one_sample.at(finest), kRasterAgreementTolerance);
  return p;
}

}  // namespace

struct RasterTradeoff::Impl {
  State state = State::idle;
  RasterTradeoffOptions options;
  std::vector<RasterTradeoffSetting> settings;
  std::vector<RasterTradeoffRow> rows;
  std::vector<std::string> notes;
  std::string error;
  int width = 0, height = 0;
  Clock::time_point started, ended;

  std::atomic<bool> cancel{false};
  std::future<Prepared> job;  // the worker; throws what the references threw
  Prepared prepared;
  std::vector<Measured> measured;  // the distinct raster configurations, in settings order
  std::size_t units_done = 0;      // configuration frame pairs drawn, runs * measured.size() in all
  std::unique_ptr<RasterRenderer> renderer;

  std::size_t units_total() const {
    return measured.size() * static_cast<std::size_t>(options.runs);
  }

  void end(State s) {
    state = s;
    ended = Clock::now();
    renderer.reset();  // shadow maps of 2048 texels hold 100 MB per light
    prepared = Prepared{};
  }

  // Draws one configuration two or three times. The first frame switches to it (meshes uploaded,
  // shadow maps redrawn when their size or the geometry changed); the second, drawn with
  // everything kept, is timed and compared, a frame of a camera drag. With shadows, a third frame
  // moves the light by kLightNudge: the shadow maps are redrawn (as in a light drag, whose cost
  // its shadow pass measures) and the next configuration's first frame redraws them again.
  // Round r starts one configuration further along, as run_tradeoff's rounds do.
  void draw_unit() {
    const std::size_t n = measured.size();
    const std::size_t run = units_done / n;
    Measured& m = measured[(units_done % n + run) % n];
    Scene& scene = prepared.scenes.at(m.config.tessellation);
    scene.render.shadows = m.config.shadows;
    renderer->render(scene, m.config.settings, false);
    const std::shared_ptr<RenderedFrame> frame = renderer->render(scene, m.config.settings, false);
    const RasterTiming& t = renderer->timing();
    m.total_ms.push_back(t.total_ms());
    m.draw_ms.push_back(t.draw_ms);
    if (!m.compared) {
      m.error = compare_images(frame->images.total, prepared.reference);
      m.pct_agree =
          percent_within(frame->images.total, prepared.one_sample.at(m.config.tessellation),
                         kRasterAgreementTolerance);
      m.compared = true;
    }
    if (m.config.shadows && !scene.lights.empty()) {
      const glm::vec3 position = scene.lights[0].position;
      scene.lights[0].position.x += kLightNudge;
      renderer->render(scene, m.config.settings, false);
      scene.lights[0].position = position;
      m.shadow_ms.push_back(renderer->timing().shadow_ms);
    }
    ++units_done;
  }

  void assemble_rows() {
    rows.clear();
    for (const RasterTradeoffSetting& s : settings) {
      if (s.cpu) {
        rows.push_back(prepared.cpu);
        continue;
      }
      const auto m = std::find_if(measured.begin(), measured.end(),
                                  [&](const Measured& x) { return x.config == s.config; });
      RasterTradeoffRow row;
      row.knob = s.knob;
      row.setting = s.setting;
      row.time_ms = median(m->total_ms);
      row.draw_ms = median(m->draw_ms);
      row.shadow_ms = median(m->shadow_ms);  // 0 without shadows
      row.error = m->error;
      row.pct_agree = m->pct_agree;
      row.base_setting = s.base;
      rows.push_back(row);
    }
  }
};

RasterTradeoff::RasterTradeoff() : m_impl(std::make_unique<Impl>()) {}

RasterTradeoff::~RasterTradeoff() {
  m_impl->cancel = true;
  if (m_impl->job.valid()) m_impl->job.wait();
}

void RasterTradeoff::start(const Scene& scene, const RasterTradeoffOptions& options) {
  Impl& m = *m_impl;
  TradeoffOptions size;
  size.width = options.width;
  size.height = options.height;
  int width = 0, height = 0;
  tradeoff_image_size(scene, size, width, height);
  const bool teapot = has_object_type(scene, ObjectType::teapot);
  const int finest = teapot && !options.tessellation_levels.empty()
                         ? *std::max_element(options.tessellation_levels.begin(),
                                             options.tessellation_levels.end())
                         : 0;
  std::vector<RasterTradeoffSetting> settings = raster_tradeoff_settings(scene, options, finest);
  if (m.job.valid()) {
    m.cancel = true;
    m.job.wait();
    m.job = {};
  }
  m.cancel = false;
  m.options = options;
  m.settings = std::move(settings);
  m.width = width;
  m.height = height;
  m.measured.clear();
  for (const RasterTradeoffSetting& s : m.settings) {
    const bool seen = std::any_of(m.measured.begin(), m.measured.end(),
                                  [&](const Measured& x) { return x.config == s.config; });
    if (!s.cpu && !seen) m.measured.push_back(Measured{s.config, {}, {}, {}, {}, 0.0, false});
  }
  m.units_done = 0;
  m.rows.clear();
  m.error.clear();
  m.notes = {
      "error: total image against render_reference<double> at " +
          std::to_string(options.reference_spp) +
          " spp (gloss-cli tradeoff's reference), every pixel; agree: % of pixels within 1e-3 "
          "on every channel of the 1-spp double image of the row's scene",
      "raster time: a frame drawn after one of the same settings (meshes and shadow maps kept, "
      "as in a camera drag), total read back; shadow_ms: the shadow pass a light drag adds",
      "cpu 1 spp: the ray tracer's render() at 1 spp, BVH build included, as gloss-cli tradeoff "
      "times its rows"};
  if (!teapot) m.notes.push_back("raster-tessellation: skipped, the scene has no teapot");
  if (!scene.render.shadows) {
    m.notes.push_back(
        "shadows are off in the scene: every shadow-map and bias row draws the image of 'off'");
  }
  m.started = m.ended = Clock::now();
  m.state = State::references;
  // The worker owns its copies; it touches this object only through m.cancel. The destructor
  // and start() join it, so m outlives it.
  m.job = std::async(std::launch::async, [&m, copy = scene, options, width, height, finest]() {
    return prepare(copy, options, width, height, finest, m.cancel);
  });
}

bool RasterTradeoff::step(double budget_ms) {
  Impl& m = *m_impl;
  if (m.options.cancel != nullptr && m.options.cancel->load()) m.cancel = true;
  bool changed = false;
  if (m.state == State::references) {
    if (m.job.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return false;
    try {
      m.prepared = m.job.get();
    } catch (const std::exception& e) {
      m.error = e.what();
      m.end(State::failed);
      return true;
    }
    m.state = State::rendering;
    changed = true;
  }
  if (m.state != State::rendering) return changed;
  if (m.cancel) {
    m.end(State::cancelled);
    return true;
  }
  try {
    if (!m.renderer) m.renderer = std::make_unique<RasterRenderer>();
    const Clock::time_point start = Clock::now();
    do {
      m.draw_unit();
    } while (m.units_done < m.units_total() && ms_since(start) < budget_ms && !m.cancel);
    if (m.units_done == m.units_total()) {
      m.assemble_rows();
      m.end(State::done);
    }
  } catch (const std::exception& e) {
    m.error = e.what();
    m.end(State::failed);
  }
  return true;
}

void RasterTradeoff::cancel() {
  m_impl->cancel = true;
}

RasterTradeoff::State RasterTradeoff::state() const {
  return m_impl->state;
}

bool RasterTradeoff::running() const {
  return m_impl->state == State::references || m_impl->state == State::rendering;
}

const std::vector<RasterTradeoffRow>& RasterTradeoff::rows() const {
  return m_impl->rows;
}

const std::vector<std::string>& RasterTradeoff::notes() const {
  return m_impl->notes;
}

const std::string& RasterTradeoff::error() const {
  return m_impl->error;
}

double RasterTradeoff::progress() const {
  const Impl& m = *m_impl;
  if (m.state == State::done) return 1.0;
  if (m.state != State::rendering || m.units_total() == 0) return 0.0;
  return 0.1 + 0.9 * static_cast<double>(m.units_done) / static_cast<double>(m.units_total());
}

double RasterTradeoff::elapsed_s() const {
  const Clock::time_point end = running() ? Clock::now() : m_impl->ended;
  return std::chrono::duration<double>(end - m_impl->started).count();
}

int RasterTradeoff::width() const {
  return m_impl->width;
}

int RasterTradeoff::height() const {
  return m_impl->height;
}

const RasterTradeoffOptions& RasterTradeoff::options() const {
  return m_impl->options;
}

std::vector<RasterTradeoffRow> measure_raster_tradeoff(const Scene& scene,
                                                       const RasterTradeoffOptions& options) {
  RasterTradeoff t;
  t.start(scene, options);
  while (t.running()) {
    // While the worker renders the references there is nothing for this thread to do.
    if (!t.step(1e12)) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  if (t.state() == RasterTradeoff::State::failed) {
    throw std::runtime_error("raster tradeoff: " + t.error());
  }
  return t.rows();
}

}  // namespace gloss
