#include "editor/model/document/command_layer.h"

#include <utility>

#include "io/scene/scene_files.h"
#include "scene/memory/scene_bytes.h"

namespace gloss {

CommandLayer::CommandLayer(Scene scene) : m_scene(std::move(scene)) {}

bool CommandLayer::execute(const Command& command) {
  Scene next = m_scene;
  apply_command(command, next);
  if (same_scene(next, m_scene)) return false;

  const std::string key = merge_key(command);
  const bool merge = m_open && !key.empty() && !m_undo.empty() && m_undo.back().key == key;
  if (merge) {
    // The step keeps the document from before the gesture; its state id changes because the
    // document after it did.
    m_undo.back().label = command_label(command);
    m_undo.back().state = m_next_state++;
    account(m_undo.back(), next);
  } else {
    m_undo.push_back({command_label(command), key, m_scene, m_next_state++});
    account(m_undo.back(), next);
    if (m_undo.size() > kMaxSteps) m_undo.erase(m_undo.begin());
  }
  m_redo.clear();
  drop_oldest_over_budget();
  m_scene = std::move(next);
  m_open = !key.empty();
  ++m_revision;
  return true;
}

std::string CommandLayer::undo_label() const {
  return m_undo.empty() ? std::string() : m_undo.back().label;
}

std::string CommandLayer::redo_label() const {
  return m_redo.empty() ? std::string() : m_redo.back().label;
}

bool CommandLayer::undo() {
  m_open = false;
  if (m_undo.empty()) return false;
  Step step = std::move(m_undo.back());
  m_undo.pop_back();
  std::swap(step.other, m_scene);
  if (step.opens) std::swap(step.other_saved, m_saved_state);
  account(step, m_scene);
  m_redo.push_back(std::move(step));
  ++m_revision;
  return true;
}

bool CommandLayer::redo() {
  m_open = false;
  if (m_redo.empty()) return false;
  Step step = std::move(m_redo.back());
  m_redo.pop_back();
  std::swap(step.other, m_scene);
  if (step.opens) std::swap(step.other_saved, m_saved_state);
  account(step, m_scene);
  m_undo.push_back(std::move(step));
  ++m_revision;
  return true;
}

void CommandLayer::reset(Scene scene, bool saved) {
  m_scene = std::move(scene);
  m_undo.clear();
  m_redo.clear();
  m_open = false;
  // State 0 is "no step applied"; a fresh id that no step carries keeps the document dirty.
  m_saved_state = saved ? 0 : m_next_state++;
  ++m_revision;
}

}  // namespace gloss

namespace gloss {

bool CommandLayer::open_document(std::shared_ptr<const Scene> scene, const std::string& label) {
  const std::uint64_t saved_before = m_saved_state;
  if (!execute(ReplaceScene{std::move(scene), label})) {
    mark_saved();
    return false;
  }
  Step& step = m_undo.back();
  step.opens = true;
  step.other_saved = saved_before;
  m_open = false;
  mark_saved();
  return true;
}

void CommandLayer::set_path(const std::string& path) {
  rebase_scene_files(m_scene, path);
  // From the newest step back to the step that opened this document (exclusive): undo steps
  // hold the document before them, redo steps the document after them.
  for (auto it = m_undo.rbegin(); it != m_undo.rend() && !it->opens; ++it) {
    rebase_scene_files(it->other, path);
  }
  for (auto it = m_redo.rbegin(); it != m_redo.rend() && !it->opens; ++it) {
    rebase_scene_files(it->other, path);
  }
  ++m_revision;
}

}  // namespace gloss

namespace gloss {

namespace {

std::uint64_t text_bytes(const std::string& s) {
  return s.capacity() > std::string().capacity() ? s.capacity() + 1 : 0;
}

}  // namespace

void CommandLayer::account(Step& step, const Scene& beside) {
  // sizeof(Step) holds sizeof(Scene), which scene_bytes_without_meshes counts too.
  step.bytes = sizeof(Step) - sizeof(Scene) + text_bytes(step.label) + text_bytes(step.key) +
               scene_bytes_without_meshes(step.other) + unshared_mesh_bytes(step.other, beside);
}

std::uint64_t CommandLayer::history_bytes() const {
  std::uint64_t total = 0;
  for (const Step& step : m_undo) total += step.bytes;
  for (const Step& step : m_redo) total += step.bytes;
  return total;
}

void CommandLayer::drop_oldest_over_budget() {
  std::uint64_t total = history_bytes();
  std::size_t drop = 0;
  while (total > kMaxHistoryBytes && m_undo.size() - drop > 1) total -= m_undo[drop++].bytes;
  m_undo.erase(m_undo.begin(), m_undo.begin() + static_cast<std::ptrdiff_t>(drop));
}

}  // namespace gloss
