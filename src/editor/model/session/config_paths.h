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

// $XDG_DATA_HOME/gloss, else $HOME/.local/share/gloss; created when missing (same fallback).
// The user's material library is its materials/ folder (material_library_folder.h).
std::filesystem::path data_dir();

// The user's documents folder: XDG_DOCUMENTS_DIR of $XDG_CONFIG_HOME/user-dirs.dirs (else
// ~/.config/user-dirs.dirs, as xdg-user-dirs writes it), else $HOME/Documents when it exists,
// else $HOME, else the current folder. Where Save as and exports start before the user has
// chosen a folder of their own (file_defaults.h).
std::filesystem::path documents_dir();

}  // namespace gloss
