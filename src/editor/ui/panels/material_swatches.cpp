#include "editor/ui/panels/material_swatches.h"

#include <chrono>
#include <cstring>

#include <sys/resource.h>

#include "editor/model/session/background_priority.h"
#include "editor/ui/panels/swatches.h"

namespace gloss {

namespace {

// The material's values as bytes: equal keys, equal swatches.
std::string key_of(const Material& m) {
  const float values[13] = {m.ambient.x,  m.ambient.y,  m.ambient.z,  m.diffuse.x,  m.diffuse.y,
                            m.diffuse.z,  m.specular.x, m.specular.y, m.specular.z, m.emission.x,
                            m.emission.y, m.emission.z, m.shininess};
  std::string key(sizeof values, '\0');
  std::memcpy(key.data(), values, sizeof values);
  return key;
}

std::vector<unsigned char> render_in_background(const Material& material) {
  // At the background priority from its first instruction (the editor's scan of new threads
  // comes a quarter second later, when a swatch is long done).
  setpriority(PRIO_PROCESS, static_cast<id_t>(current_thread_id()), kBackgroundNice);
  return render_swatch(material);
}

}  // namespace

MaterialSwatches::~MaterialSwatches() {
  if (m_job.valid()) m_job.wait();
}

GLuint MaterialSwatches::texture(const std::string& slot, const Material& material) {
  const std::string key = key_of(material);
  const auto it = m_slots.find(slot);
  const bool shown = it != m_slots.end() && it->second.key == key;
  const bool rendering = m_job.valid() && m_job_slot == slot && m_job_key == key;
  if (!shown && !rendering) {
    m_wanted[slot] = material;
  } else {
    m_wanted.erase(slot);
  }
  return it == m_slots.end() ? 0 : it->second.texture.id();
}

void MaterialSwatches::poll() {
  if (m_job.valid()) {
    if (m_job.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return;
    Slot& slot = m_slots[m_job_slot];
    slot.key = m_job_key;  // shown, or failed: either way not asked for again
    try {
      const std::vector<unsigned char> rgb = m_job.get();
      slot.texture.upload_rgb8(Swatches::kSize, Swatches::kSize, rgb.data());
    } catch (const std::exception&) {
      // A material the renderer refuses keeps its last swatch (or grey square).
    }
  }
  if (m_wanted.empty()) return;
  const auto next = m_wanted.begin();
  m_job_slot = next->first;
  m_job_key = key_of(next->second);
  m_job = std::async(std::launch::async, render_in_background, next->second);
  m_wanted.erase(next);
}

std::size_t MaterialSwatches::texture_bytes() const {
  return m_slots.size() * Swatches::kSize * Swatches::kSize * 3;
}

}  // namespace gloss
