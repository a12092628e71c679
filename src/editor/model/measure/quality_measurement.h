#pragma once
// The Quality panel's measurement: run_tradeoff (analysis/tradeoff/tradeoff.h) on a worker thread
// over a copy of the scene, its rows collected for the UI thread as each knob finishes, cancellable
// at any time. No GL: the unit tests drive it directly. Also the pure helpers the panel and scripts
// share: the one-line verdict per knob and the command (or preview scale) that applies a measured
// setting.
#include <atomic>
#include <chrono>
#include <future>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "analysis/tradeoff/tradeoff.h"
#include "editor/model/document/command.h"

namespace gloss {

class QualityMeasurement {
 public:
  enum class State { idle, running, done, cancelled, failed };

  QualityMeasurement() = default;
  QualityMeasurement(const QualityMeasurement&) = delete;
  QualityMeasurement& operator=(const QualityMeasurement&) = delete;
  ~QualityMeasurement();  // cancels a running measurement and joins its worker

  // Starts measuring a copy of scene; returns at once. A measurement already running is cancelled
  // and joined first (a render or two, milliseconds at the quick settings). options.cancel is
  // replaced by this object's flag. Throws std::invalid_argument for options out of range.
  void start(const Scene& scene, TradeoffOptions options = quick_tradeoff_options());
  // Asks the worker to stop; returns at once. poll() reports State::cancelled once it has.
  void cancel();
  // Blocks until the worker has ended, then polls (scripts and tests).
  void wait();
  // UI thread, once a frame: takes the rows that arrived and the worker's end. True on change.
  bool poll();

  State state() const { return m_state; }
  bool running() const { return m_state == State::running; }
  // True while a worker thread exists (running, or ended but not yet polled).
  bool worker_alive() const { return m_job.valid(); }
  const std::vector<TradeoffRow>& rows() const { return m_rows; }
  const std::vector<std::string>& notes() const { return m_notes; }
  // The knobs this measurement covers, in run order (tessellation only for a teapot scene).
  const std::vector<Knob>& knobs() const { return m_knobs; }
  // Knobs whose rows have all arrived.
  int knobs_done() const;
  // The knob being measured while running (the first one also renders the reference); else nothing.
  std::optional<Knob> current_knob() const;
  const std::string& error() const { return m_error; }
  // Seconds since start while running; the measurement's duration after it ended.
  double elapsed_s() const;
  int width() const { return m_width; }  // measured image size, pixels
  int height() const { return m_height; }
  const TradeoffOptions& options() const { return m_options; }
  // True when current differs from the measured copy in anything the measurement depends on. The
  // target spp, pow mode, seed, display encoding and file path do not count: run_tradeoff sets
  // spp and pow itself, and the others do not change the linear image.
  bool stale(const Scene& current) const;

 private:
  using Clock = std::chrono::steady_clock;

  State m_state = State::idle;
  Scene m_scene;  // the copy measured (the worker reads its own copy)
  TradeoffOptions m_options;
  std::vector<Knob> m_knobs;
  std::vector<TradeoffRow> m_rows;
  std::vector<std::string> m_notes;
  std::string m_error;
  int m_width = 0, m_height = 0;
  Clock::time_point m_started, m_ended;

  std::atomic<bool> m_cancel{false};
  std::mutex m_mutex;                   // guards m_incoming
  std::vector<TradeoffRow> m_incoming;  // rows from the worker not yet taken by poll()
  std::future<void> m_job;              // the worker; throws what run_tradeoff threw
};

// The rows of one knob, in measured order.
std::vector<TradeoffRow> rows_of_knob(const std::vector<TradeoffRow>& rows, Knob knob);

// One line that helps choose a setting of one knob: the cheapest setting whose image is within
// 1/255 of the reference on 99% of pixels (pct_pixels_off <= 1). When none is (every row carries
// the base's own error), the cheapest setting at least 5% faster than the knob's reference setting
// (else its most accurate row) and as good: at most 1 point more pixels off, 1.5x the RMSE.
std::string quality_verdict(const std::vector<TradeoffRow>& knob_rows);

// The document command that gives scene exactly the setting the row measured, or nothing for
// knobs the editor does not carry as document settings: spp rows were measured with uniform
// sampling (spp N and uniform), adaptive rows with adaptive sampling at their spp and threshold
// ("16 t=1/64"; its "uniform" row is the base, quick_tradeoff_options().base_spp uniform),
// shadows on/off, pow fast/exact. A row that changes several fields is one command (one undo
// step).
std::optional<Command> command_for_row(const TradeoffRow& row, const Scene& scene);
// The viewport preview scale for a resolution row ("1/2" -> 0.5), or nothing when the row is
// not a resolution row or its scale is outside the editor's 0.25..1.
std::optional<float> preview_scale_for_row(const TradeoffRow& row);
// True when the scene (and preview scale) already use the row's setting: what command_for_row
// would set is what the scene has.
bool row_in_use(const TradeoffRow& row, const Scene& scene, float preview_scale);

// Writes tradeoff_to_csv(rows) to path atomically; throws RuntimeFailure when it cannot.
void write_quality_csv(const std::string& path, const std::vector<TradeoffRow>& rows);

}  // namespace gloss
