#pragma once
// The frame loop's clock and bookkeeping: when the editor started (the frame clock every
// notice, gesture and latency probe counts from), the UI's frame times, and what run_frame keeps
// between frames for its housekeeping.
#include <chrono>
#include <cstdint>
#include <string>

#include "editor/model/session/background_priority.h"

namespace gloss {

// Seconds since the editor started: the frame clock.
struct Clock {
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  double now_s() const;
};

// UI frame times (CPU time from the start of a frame to after its buffer swap), last 240.
struct FrameTimes {
  static constexpr int kCount = 240;
  double ms[kCount] = {};
  int size = 0, next = 0;
  void add(double value);
  double average() const;
  double median() const;  // the Speed targets are medians: one stall does not move it
  double largest() const;
};

struct FrameLoop {
  FrameTimes times;
  double last_frame_s = 0.0;      // start of the previous frame (orbit-light animation step)
  BackgroundPriority background;  // render and export threads below the UI (created on it)
  double background_checked_s = -1.0;
  std::uint64_t released_at_upload = 0;  // viewport.uploads() when free memory was last released
  std::string title;                     // the window title last set
};

}  // namespace gloss
