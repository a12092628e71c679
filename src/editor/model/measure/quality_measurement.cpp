#include "editor/model/measure/quality_measurement.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <memory>

#include "base/atomic_file.h"
#include "editor/model/document/document.h"

namespace gloss {

namespace {

// The map knobs have rows only for a scene with maps (tradeoff.h).
bool has_maps(const Scene& scene) {
  return std::any_of(scene.materials.begin(), scene.materials.end(),
                     [](const Material& m) { return m.textured(); });
}

bool has_teapot(const Scene& scene) {
  return std::any_of(scene.objects.begin(), scene.objects.end(),
                     [](const Object& o) { return o.type == ObjectType::teapot; });
}

// What a staleness check compares: the settings run_tradeoff overrides or that do not change the
// linear image are made equal. The display transform (exposure, tone, encoding) counts: adaptive
// sampling's placement reads the displayed image, so the adaptive rows depend on it.
Scene measured_part(Scene scene) {
  scene.render.spp = 1;
  scene.render.sampling = Sampling::uniform;  // each row sets its sampling and threshold
  scene.render.aa_threshold = 0.0f;
  scene.render.pow = PowMode::exact;
  scene.render.seed = 0;
  scene.path.clear();
  return scene;
}

// "1/4" -> 4, "1" -> 1; 0 when the text is not a divisor.
int divisor_of(const std::string& setting) {
  if (setting == "1") return 1;
  if (setting.rfind("1/", 0) != 0) return 0;
  const int d = std::atoi(setting.c_str() + 2);
  return d >= 1 ? d : 0;
}

std::string format_ms(double ms) {
  char text[32];
  std::snprintf(text, sizeof text, ms < 10.0 ? "%.2f ms" : "%.0f ms", ms);
  return text;
}

}  // namespace

QualityMeasurement::~QualityMeasurement() {
  m_cancel = true;
  if (m_job.valid()) m_job.wait();
}

void QualityMeasurement::start(const Scene& scene, TradeoffOptions options) {
  if (m_job.valid()) {
    m_cancel = true;
    m_job.wait();
    m_job = {};
  }
  m_cancel = false;
  options.cancel = &m_cancel;
  m_scene = scene;
  m_options = options;
  m_knobs.clear();
  for (const Knob knob : tradeoff_knobs()) {
    const bool chosen =
        options.knobs.empty() ||
        std::find(options.knobs.begin(), options.knobs.end(), knob) != options.knobs.end();
    // Knobs a scene has no rows for (tradeoff.h): no teapot, no environment, no maps.
    const bool maps = knob == Knob::map_filter || knob == Knob::map_resolution;
    const bool environment = knob == Knob::env_samples || knob == Knob::env_resolution;
    if (chosen && (knob != Knob::tessellation || has_teapot(scene)) && (!maps || has_maps(scene)) &&
        (!environment || scene.environment.present())) {
      m_knobs.push_back(knob);
    }
  }
  m_rows.clear();
  m_incoming.clear();
  m_error.clear();
  m_notes = tradeoff_notes(scene, options);
  tradeoff_image_size(scene, options, m_width, m_height);
  m_started = m_ended = Clock::now();
  m_state = State::running;
  // The worker owns its copy of the scene (meshes are shared and never modified in place); it
  // only touches this object through m_incoming (under m_mutex) and m_cancel. The destructor
  // and start() join it, so `this` outlives it.
  m_job = std::async(std::launch::async, [this, copy = scene, options]() {
    run_tradeoff(copy, options, [this](const TradeoffRow& row) {
      std::lock_guard<std::mutex> lock(m_mutex);
      m_incoming.push_back(row);
      return !m_cancel.load();
    });
  });
}

void QualityMeasurement::cancel() {
  m_cancel = true;
}

void QualityMeasurement::wait() {
  if (m_job.valid()) m_job.wait();
  poll();
}

bool QualityMeasurement::poll() {
  bool changed = false;
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    if (!m_incoming.empty()) {
      m_rows.insert(m_rows.end(), m_incoming.begin(), m_incoming.end());
      m_incoming.clear();
      changed = true;
    }
  }
  if (!m_job.valid() || m_job.wait_for(std::chrono::seconds(0)) != std::future_status::ready) {
    return changed;
  }
  try {
    m_job.get();
    m_state = m_cancel ? State::cancelled : State::done;
  } catch (const std::exception& e) {
    m_error = e.what();
    m_state = State::failed;
  }
  m_ended = Clock::now();
  // Rows pushed between the check above and the worker's end.
  std::lock_guard<std::mutex> lock(m_mutex);
  m_rows.insert(m_rows.end(), m_incoming.begin(), m_incoming.end());
  m_incoming.clear();
  return true;
}

int QualityMeasurement::knobs_done() const {
  int done = 0;
  for (const Knob knob : m_knobs) {
    const bool any = std::any_of(m_rows.begin(), m_rows.end(),
                                 [&](const TradeoffRow& r) { return r.knob == knob; });
    done += any ? 1 : 0;
  }
  return done;
}

std::optional<Knob> QualityMeasurement::current_knob() const {
  if (!running()) return std::nullopt;
  const std::size_t done = static_cast<std::size_t>(knobs_done());
  if (done < m_knobs.size()) return m_knobs[done];
  return std::nullopt;
}

double QualityMeasurement::elapsed_s() const {
  const Clock::time_point end = running() ? Clock::now() : m_ended;
  return std::chrono::duration<double>(end - m_started).count();
}

bool QualityMeasurement::stale(const Scene& current) const {
  if (m_state == State::idle) return false;
  return !same_scene(measured_part(m_scene), measured_part(current));
}

std::vector<TradeoffRow> rows_of_knob(const std::vector<TradeoffRow>& rows, Knob knob) {
  std::vector<TradeoffRow> out;
  std::copy_if(rows.begin(), rows.end(), std::back_inserter(out),
               [&](const TradeoffRow& r) { return r.knob == knob; });
  return out;
}

std::string quality_verdict(const std::vector<TradeoffRow>& knob_rows) {
  if (knob_rows.empty()) return "";
  const TradeoffRow* cheapest_good = nullptr;
  for (const TradeoffRow& r : knob_rows) {
    if (r.error.pct_pixels_off <= 1.0 &&
        (cheapest_good == nullptr || r.time_ms < cheapest_good->time_ms)) {
      cheapest_good = &r;
    }
  }
  if (cheapest_good != nullptr) {
    return cheapest_good->setting + ": the cheapest within 1/255 on 99% of pixels (" +
           format_ms(cheapest_good->time_ms) + ")";
  }
  // The anchor: the knob's reference setting, else its most accurate row.
  const TradeoffRow* anchor = &knob_rows.front();
  for (const TradeoffRow& r : knob_rows) {
    if (anchor->reference_setting) break;
    if (r.reference_setting || r.error.pct_pixels_off < anchor->error.pct_pixels_off) anchor = &r;
  }
  // As good: at most 1 point more pixels off and 1.5x the RMSE. Cheaper: at least 5% faster, so
  // that timing noise (a few % under load) does not pick a setting.
  const TradeoffRow* choice = anchor;
  for (const TradeoffRow& r : knob_rows) {
    const bool as_good = r.error.pct_pixels_off <= anchor->error.pct_pixels_off + 1.0 &&
                         r.error.rmse <= 1.5 * anchor->error.rmse;
    if (as_good && r.time_ms <= 0.95 * anchor->time_ms && r.time_ms < choice->time_ms) {
      choice = &r;
    }
  }
  if (choice == anchor) return "keep " + anchor->setting + ": nothing 5% cheaper is as good";
  return choice->setting + ": as good as " + anchor->setting + " at " + format_ms(choice->time_ms) +
         " vs " + format_ms(anchor->time_ms);
}

namespace {

// The render settings a row of the spp or adaptive knob was measured with, applied to render;
// false for other rows or settings that do not parse.
bool sampling_of_row(const TradeoffRow& row, RenderSettings& render) {
  if (row.knob == Knob::spp) {
    const int spp = std::atoi(row.setting.c_str());
    if (spp < 1 || spp > kMaxSpp) return false;
    render.spp = spp;
    // 1 spp is the pixel centre either way: the scene's sampling stays as it is.
    if (spp > 1) render.sampling = Sampling::uniform;
    return true;
  }
  if (row.knob != Knob::adaptive) return false;
  if (row.setting == "uniform") {  // the base the adaptive rows are weighed against
    render.spp = quick_tradeoff_options().base_spp;
    render.sampling = Sampling::uniform;
    return true;
  }
  int spp = 0, divisor = 0;  // "16 t=1/64"
  if (std::sscanf(row.setting.c_str(), "%d t=1/%d", &spp, &divisor) != 2 || spp < 1 ||
      spp > kMaxSpp || divisor < 1) {
    return false;
  }
  render.spp = spp;
  render.sampling = Sampling::adaptive;
  render.aa_threshold = 1.0f / static_cast<float>(divisor);
  return true;
}

}  // namespace

std::optional<Command> command_for_row(const TradeoffRow& row, const Scene& scene) {
  if (RenderSettings render = scene.render; sampling_of_row(row, render)) {
    auto next = std::make_shared<Scene>(scene);
    next->render = render;
    return Command(ReplaceScene{std::move(next), "use " + std::string(to_string(row.knob)) + " " +
                                                     row.setting + " (Quality window)"});
  }
  if (row.knob == Knob::shadows && (row.setting == "on" || row.setting == "off")) {
    return Command(SetField{FieldPart::render, 0, "shadows", number_value(row.setting == "on")});
  }
  if (row.knob == Knob::env_samples || row.knob == Knob::env_resolution) {
    // "0 (fast)", "16" ...; "1", "2", "4" (the env_resolution rows have env_samples 0: "Use"
    // sets the resolution only).
    const int n = std::atoi(row.setting.c_str());
    return Command(SetField{FieldPart::render, 0, to_string(row.knob), number_value(n)});
  }
  PowMode pow = PowMode::exact;
  if (row.knob == Knob::pow && parse_pow_mode(row.setting, pow)) {
    return Command(SetField{FieldPart::render, 0, "pow", number_value(static_cast<int>(pow))});
  }
  return std::nullopt;
}

std::optional<float> preview_scale_for_row(const TradeoffRow& row) {
  if (row.knob != Knob::resolution) return std::nullopt;
  const int d = divisor_of(row.setting);
  if (d < 1 || d > 4) return std::nullopt;  // the preview scale slider's range is 0.25..1
  return 1.0f / static_cast<float>(d);
}

bool row_in_use(const TradeoffRow& row, const Scene& scene, float preview_scale) {
  if (RenderSettings render = scene.render; sampling_of_row(row, render)) {
    const bool adaptive = render.sampling == Sampling::adaptive && render.spp > 1;
    return render.spp == scene.render.spp && render.sampling == scene.render.sampling &&
           (!adaptive || render.aa_threshold == scene.render.aa_threshold);
  }
  if (row.knob == Knob::shadows) return scene.render.shadows == (row.setting == "on");
  if (row.knob == Knob::pow) return to_string(scene.render.pow) == row.setting;
  if (row.knob == Knob::env_samples) {
    return scene.render.env_samples == std::atoi(row.setting.c_str());
  }
  if (row.knob == Knob::env_resolution) {
    return scene.render.env_resolution == std::atoi(row.setting.c_str());
  }
  if (const std::optional<float> scale = preview_scale_for_row(row)) {
    return std::fabs(*scale - preview_scale) < 1e-3f;
  }
  return false;
}

void write_quality_csv(const std::string& path, const std::vector<TradeoffRow>& rows) {
  write_text_atomically(path, tradeoff_to_csv(rows));
}

}  // namespace gloss
