#include "editor/model/view/albedo_curves.h"

#include <chrono>

namespace gloss {

AlbedoCurves::~AlbedoCurves() {
  m_cancel.store(true);
  if (m_job.valid()) m_job.wait();
}

void AlbedoCurves::collect() {
  if (!m_job.valid() || m_job.wait_for(std::chrono::seconds(0)) != std::future_status::ready) {
    return;
  }
  std::vector<AlbedoTerms> curve = m_job.get();
  if (curve.empty()) return;  // cancelled
  m_curve = std::move(curve);
  m_done_params = m_job_params;
  m_done = true;
}

const std::vector<AlbedoTerms>* AlbedoCurves::get(const AlbedoParams& params) {
  m_asked = params;
  collect();
  const bool have = m_done && m_done_params == params;
  if (!have && !m_job.valid()) {
    m_job_params = params;
    m_cancel.store(false);
    m_job = std::async(std::launch::async, [params, this] {
      return albedo_curve(params, kAlbedoAngles, kAlbedoMaxDeg, &m_cancel);
    });
  }
  return m_done ? &m_curve : nullptr;
}

}  // namespace gloss
