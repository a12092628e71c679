#include "cli/scene_messages.h"

#include <iostream>

#include "base/text/printable_text.h"

namespace gloss {

void print_scene_messages(const std::vector<std::string>& notes,
                          const std::vector<std::string>& warnings) {
  for (const std::string& note : notes) std::cerr << "note: " << printable_text(note) << "\n";
  for (const std::string& warning : warnings) {
    std::cerr << "warning: " << printable_text(warning) << "\n";
  }
}

}  // namespace gloss
