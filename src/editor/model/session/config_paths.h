#pragma once
// Where the editor keeps its own files. Settings (imgui.ini, recent files) follow the XDG base
// directory rules for configuration; the crash-recovery file is state, not configuration.
#include <filesystem>

namespace gloss {

// $XDG_CONFIG_HOME/gloss, else $HOME/.config/gloss; created when missing. Without either
// variable: a gloss folder in the system's temporary directory.
std::filesystem::path config_dir();

// $XDG_STATE_HOME/gloss, else $HOME/.local/state/gloss; created when missing (same fallback).
std::filesystem::path state_dir();

}  // namespace gloss
