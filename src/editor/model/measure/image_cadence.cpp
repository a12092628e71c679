#include "editor/model/measure/image_cadence.h"

#include <algorithm>
#include <vector>

#include "base/timing.h"

namespace gloss {

namespace {
// A window keeps at most this many images and delays (minutes of 60 Hz frames): a session that
// never asks for `stats` does not grow.
constexpr std::size_t kKept = 16384;

template <class T>
void push_capped(std::deque<T>& values, T value) {
  values.push_back(value);
  if (values.size() > kKept) values.pop_front();
}
}  // namespace

void ImageCadence::edit(std::uint64_t generation, double now_s) {
  if (m_window_s < 0) m_window_s = now_s;
  if (!m_pending.empty() && m_pending.back().generation >= generation) return;  // the same one
  push_capped(m_pending, Pending{generation, now_s});
}

ImageCadence::Delays ImageCadence::shown(std::uint64_t generation, bool full_size, double now_s) {
  if (m_window_s < 0) m_window_s = now_s;
  Delays out;
  bool first = false;
  while (!m_pending.empty() && m_pending.front().generation <= generation) {
    m_shown = m_pending.front();  // the newest edit the frame shows: its own
    m_pending.pop_front();
    first = true;
  }
  if (first) {
    out.first_ms = (now_s - m_shown.edit_s) * 1000.0;
    push_capped(m_delays, out.first_ms);
    m_full_done = false;
  }
  if (full_size && !m_full_done) {
    out.full_ms = (now_s - m_shown.edit_s) * 1000.0;
    m_full_done = true;
  }
  out.generation = m_shown.generation;
  push_capped(m_images, now_s);
  return out;
}

void ImageCadence::forget_pending() {
  m_pending.clear();
  m_full_done = true;
}

ImageCadence::Window ImageCadence::window(double now_s) const {
  Window w;
  const double start = m_window_s < 0 ? now_s : m_window_s;
  w.seconds = now_s - start;
  w.images = static_cast<int>(m_images.size());
  std::vector<double> gaps;
  double last = start;
  for (const double t : m_images) {
    gaps.push_back((t - last) * 1000.0);
    last = t;
  }
  gaps.push_back((now_s - last) * 1000.0);  // the open gap
  w.max_gap_ms = *std::max_element(gaps.begin(), gaps.end());
  w.median_gap_ms = median(gaps);
  w.delays = static_cast<int>(m_delays.size());
  if (!m_delays.empty()) {
    w.median_delay_ms = median(std::vector<double>(m_delays.begin(), m_delays.end()));
    w.max_delay_ms = *std::max_element(m_delays.begin(), m_delays.end());
  }
  return w;
}

void ImageCadence::restart(double now_s) {
  m_window_s = now_s;
  m_images.clear();
  m_delays.clear();
}

}  // namespace gloss
