#pragma once
// Rendered balls of any material (the scene's materials, a user library's), for the material
// list: rendered one at a time on a worker thread at the background priority
// (editor/model/session/background_priority.h), so the UI never waits for one, and kept by the
// material's values: an edited material is rendered again, an unchanged one never. While a slot's
// new swatch renders, the slot shows its last one.
#include <future>
#include <map>
#include <string>
#include <vector>

#include "editor/gl/gl_texture.h"
#include "scene/material.h"

namespace gloss {

class MaterialSwatches {
 public:
  MaterialSwatches() = default;
  ~MaterialSwatches();  // waits for the swatch in flight (a few milliseconds)
  MaterialSwatches(const MaterialSwatches&) = delete;
  MaterialSwatches& operator=(const MaterialSwatches&) = delete;

  // The swatch of slot (a name: "scene:gold", "library:brass.json:brass"), or 0 before its first
  // one is ready; asks for material's when the slot shows another.
  GLuint texture(const std::string& slot, const Material& material);
  // On the UI thread, once a frame: uploads a finished swatch and starts the next one asked for.
  void poll();
  // Swatches waiting or rendering (0 when all are shown).
  std::size_t pending() const { return m_wanted.size() + (m_job.valid() ? 1 : 0); }
  std::size_t texture_bytes() const;

 private:
  struct Slot {
    std::string key;  // the values its texture shows
    GlTexture texture;
  };
  std::map<std::string, Slot> m_slots;
  std::map<std::string, Material> m_wanted;  // slot -> the newest material asked for
  std::future<std::vector<unsigned char>> m_job;
  std::string m_job_slot, m_job_key;
};

}  // namespace gloss
