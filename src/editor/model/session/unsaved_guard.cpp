#include "editor/model/session/unsaved_guard.h"

#include <utility>

namespace gloss {

bool UnsavedGuard::request_open(const std::string& path, bool dirty) {
  if (!dirty) return true;
  m_asking = true;
  m_path = path;
  return false;
}

UnsavedGuard::Outcome UnsavedGuard::answer(UnsavedAnswer answer) {
  Outcome outcome;
  if (!m_asking) return outcome;
  m_asking = false;
  if (answer != UnsavedAnswer::cancel) {
    outcome.save_first = answer == UnsavedAnswer::save;
    outcome.open = true;
    outcome.path = std::move(m_path);
  }
  m_path.clear();
  return outcome;
}

}  // namespace gloss
