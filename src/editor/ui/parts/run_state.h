#pragma once
// The editor's run: the script it plays, and whether and how it ends. main.cpp's loop runs
// frames until quit.
#include <memory>

namespace gloss {

class ScriptPlayer;

struct RunState {
  std::unique_ptr<ScriptPlayer> script;  // null without --script, and once the script ended
  bool quit = false;
  int exit_code = 0;
};

}  // namespace gloss
