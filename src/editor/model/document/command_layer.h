#pragma once
// The one owner of the document. Every edit arrives here as a Command; the layer applies it,
// records an undo step, and counts revisions so the renderer, the autosave and the window title
// can tell that something changed. Undo restores the exact earlier document (steps keep a copy of
// the scene on the other side of the edit; meshes are shared, so copies are small).
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "editor/model/document/command.h"

namespace gloss {

class CommandLayer {
 public:
  explicit CommandLayer(Scene scene);

  const Scene& scene() const { return m_scene; }

  // Applies command and records an undo step, or merges into the open step when the command's
  // merge key equals that step's (one slider drag = one step). Returns false, recording nothing,
  // when the document did not change. Throws CommandError with the document unchanged.
  bool execute(const Command& command);

  // Ends the current gesture: the next command starts a new undo step.
  void seal() { m_open = false; }

  bool can_undo() const { return !m_undo.empty(); }
  bool can_redo() const { return !m_redo.empty(); }
  std::string undo_label() const;  // empty when there is nothing to undo
  std::string redo_label() const;
  bool undo();
  bool redo();

  // Opens another document (File > Open) as one undo step and marks it saved. The document it
  // replaces keeps its own saved/unsaved state: undoing the open gives it back exactly as it was
  // (an untouched file stays unmodified, an edited one stays modified) and redoing it gives back
  // the opened one with its state. Returns false, recording nothing, when scene equals the
  // document; the document is then marked saved. Throws CommandError as execute does.
  bool open_document(std::shared_ptr<const Scene> scene, const std::string& label);

  // Replaces the document and forgets the history. saved: the document is what its file holds
  // (false for a recovered session, which differs from its file).
  void reset(Scene scene, bool saved);

  // Records that the document now lives at path (save as): the path is the document's identity,
  // not an edit, so every undo step of this document takes it too (rebase_scene_files,
  // io/scene/scene_files.h)
  // and no step is recorded. Steps beyond an open_document step hold another document and keep
  // their path.
  void set_path(const std::string& path);

  // Changes with every change of the document (edit, undo, redo, reset); never repeats.
  std::uint64_t revision() const { return m_revision; }

  // The saved state is the one whose file is on disk; dirty() says the document differs from it.
  void mark_saved() { m_saved_state = current_state(); }
  bool dirty() const { return current_state() != m_saved_state; }

  std::size_t undo_count() const { return m_undo.size(); }
  std::size_t redo_count() const { return m_redo.size(); }
  // Steps kept; older steps are dropped (at 500 steps a gesture-sized step is ~1 scene copy).
  static constexpr std::size_t kMaxSteps = 500;
  // Bytes the undo and redo steps may hold (history_bytes); past it the oldest undo steps are
  // dropped, though never the newest one. Edits share meshes, so this bounds the steps that
  // keep replaced scenes' meshes alive (open, add model), not ordinary edits.
  static constexpr std::uint64_t kMaxHistoryBytes = std::uint64_t(64) << 20;
  // What the steps hold: each step's scene copy without meshes (scene/memory/scene_bytes.h), its
  // labels, and the meshes it alone keeps alive (not shared with the document on the other side
  // of it when it was recorded, undone or redone).
  std::uint64_t history_bytes() const;

 private:
  struct Step {
    std::string label;
    std::string key;
    Scene other;          // the document on the other side of this step
    std::uint64_t state;  // identifies the document after the step (see current_state)
    bool opens = false;   // open_document: 'other' is a different document
    // For an opening step, the saved state of the document on the other side; undo and redo
    // swap it with m_saved_state.
    std::uint64_t other_saved = 0;
    std::uint64_t bytes = 0;  // see history_bytes; set by account()
  };
  // Sets step.bytes for a step whose other side is `beside`.
  static void account(Step& step, const Scene& beside);
  void drop_oldest_over_budget();
  std::uint64_t current_state() const { return m_undo.empty() ? 0 : m_undo.back().state; }

  Scene m_scene;
  std::vector<Step> m_undo;
  std::vector<Step> m_redo;
  bool m_open = false;  // the top undo step may still absorb commands with its key
  std::uint64_t m_revision = 0;
  std::uint64_t m_next_state = 1;
  std::uint64_t m_saved_state = 0;
};

}  // namespace gloss
