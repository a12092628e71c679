#pragma once
// The lobe view's directional albedo curves (analysis/lobe/directional_albedo.h), computed on a
// worker: one curve takes 0.1 to 0.7 s (adaptive quadrature over the hemisphere at each angle),
// too long for a UI frame. The view asks each frame for the parameters it shows; a new job starts
// when the worker is idle, so a slider drag computes the newest parameters when it can and the
// view shows the last finished curve meanwhile. The shares do not depend on kd or ks, only on the
// exponents and the normalisation, so a material's colours change nothing here.
#include <atomic>
#include <future>
#include <optional>
#include <vector>

#include "analysis/lobe/directional_albedo.h"

namespace gloss {

constexpr int kAlbedoAngles = 45;          // incidence 0, 2, ... 88 degrees
constexpr double kAlbedoMaxDeg = 88.0;     // at 90 the irradiance is 0
constexpr double kAlbedoTolerance = 1e-5;  // each integral's relative error asked

class AlbedoCurves {
 public:
  AlbedoCurves() = default;
  ~AlbedoCurves();  // cancels the job in flight and joins it
  AlbedoCurves(const AlbedoCurves&) = delete;
  AlbedoCurves& operator=(const AlbedoCurves&) = delete;

  // The curve for params when finished, else the newest finished (for older parameters) or
  // null; starts computing params when the worker is free. Call from one thread.
  const std::vector<AlbedoTerms>* get(const AlbedoParams& params);
  // The curve get() returned is for the parameters asked.
  bool current() const { return m_done && m_done_params == m_asked; }
  bool busy() const { return m_job.valid(); }

 private:
  void collect();  // takes a finished job's curve

  std::future<std::vector<AlbedoTerms>> m_job;
  AlbedoParams m_job_params, m_done_params, m_asked;
  std::vector<AlbedoTerms> m_curve;
  bool m_done = false;
  std::atomic<bool> m_cancel{false};
};

}  // namespace gloss
