#pragma once
// Measures the raster tradeoff rows of a scene (raster_tradeoff_rows.h: the settings, the row,
// the CSV). The CPU part (the exact reference, the one-sample references per teapot level and the
// cpu row) runs on a worker thread; the raster frames run on the thread that owns the GL context,
// in slices of step(), so that the editor's UI thread measures between its frames and stays
// responsive. The raster settings are timed round-robin (run r draws each distinct configuration
// once), as run_tradeoff times a knob's settings, so that load from other processes falls on them
// alike.
//
// GL: step() and the destructor must run with a current GL 3.3 core context, the same one each
// time (the RasterRenderer is made on the first raster step and released when the measurement
// ends or is cancelled).
#include <memory>
#include <string>
#include <vector>

#include "editor/gl/raster/raster_tradeoff_rows.h"

namespace gloss {

class RasterTradeoff {
 public:
  // references: the worker renders the references and times the cpu row; rendering: step()
  // draws the raster frames.
  enum class State { idle, references, rendering, done, cancelled, failed };

  RasterTradeoff();
  ~RasterTradeoff();  // cancels, joins the worker, releases the renderer (context current)
  RasterTradeoff(const RasterTradeoff&) = delete;
  RasterTradeoff& operator=(const RasterTradeoff&) = delete;

  // Starts measuring a copy of scene; returns at once. A measurement in progress is cancelled and
  // its worker joined first. Throws std::invalid_argument for options out of range.
  void start(const Scene& scene, const RasterTradeoffOptions& options);
  // GL thread: once the references are ready, draws raster frames until budget_ms have passed
  // (at least one configuration's pair of frames), and assembles the rows after the last. True
  // when anything changed (state, progress).
  bool step(double budget_ms);
  // Asks the measurement to stop; the worker ends within a reference band, step() ends the rest.
  void cancel();

  State state() const;
  bool running() const;
  const std::vector<RasterTradeoffRow>& rows() const;  // all of them once done, else empty
  const std::vector<std::string>& notes() const;       // what the rows cannot say themselves
  const std::string& error() const;                    // why it failed
  double progress() const;   // 0..1: the references count as the first tenth
  double elapsed_s() const;  // since start; the duration once ended
  int width() const;         // measured image size, pixels
  int height() const;
  const RasterTradeoffOptions& options() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> m_impl;
};

// The whole measurement at once on the calling thread (GL context current), for scripts and
// tests. Throws std::runtime_error with the reason when it fails; empty when options.cancel
// turned true.
std::vector<RasterTradeoffRow> measure_raster_tradeoff(const Scene& scene,
                                                       const RasterTradeoffOptions& options);

}  // namespace gloss
