#include "editor/ui/parts/commands.h"

#include "editor/ui/notices.h"
#include "editor/ui/parts/frame_loop.h"

namespace gloss {

bool Commands::execute(const Command& command) {
  try {
    return m_document.execute(command);
  } catch (const CommandError& e) {
    error(e.what());
    return false;
  }
}

void Commands::undo() {
  const std::string label = m_document.undo_label();
  if (m_document.undo()) info("undid " + label);
}

void Commands::redo() {
  const std::string label = m_document.redo_label();
  if (m_document.redo()) info("redid " + label);
}

void Commands::info(const std::string& text) {
  m_notices.info(text, m_clock.now_s());
}

void Commands::error(const std::string& text) {
  m_notices.error(text, m_clock.now_s());
}

}  // namespace gloss
