#pragma once
// The one door through which panels and the viewport change the document: each edit is a
// Command executed by the command layer (editor/model/document/command_layer.h), which records
// the undo step; an edit the layer refuses becomes a notice instead of an exception. The door
// also reads the document, and carries the panels' other messages to the notices. Panels get
// this, never the CommandLayer itself: opening, saving and recovering whole documents are the
// app's file actions (file_actions.h).
#include <string>

#include "editor/model/document/command_layer.h"

namespace gloss {

struct Clock;
struct Notices;

class Commands {
 public:
  Commands(CommandLayer& document, Notices& notices, const Clock& clock)
      : m_document(document), m_notices(notices), m_clock(clock) {}

  const Scene& scene() const { return m_document.scene(); }
  // Revision, undo history and saved state, read only.
  const CommandLayer& document() const { return m_document; }

  // Executes command, reporting a CommandError as a notice. Returns true when the document
  // changed.
  bool execute(const Command& command);
  // One step back or forward, named in a notice; nothing when there is none.
  void undo();
  void redo();

  // A message for the user (a notice), e.g. why an action that is not a command failed.
  void info(const std::string& text);
  void error(const std::string& text);

 private:
  CommandLayer& m_document;
  Notices& m_notices;
  const Clock& m_clock;
};

}  // namespace gloss
