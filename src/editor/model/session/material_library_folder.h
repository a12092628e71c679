#pragma once
// The user's material library: a folder of materials files (gloss JSON or Wavefront MTL) in the
// XDG data folder, $XDG_DATA_HOME/gloss/materials (else ~/.local/share/gloss/materials). The
// editor shows its materials as swatches beside the 24 presets and saves the selected material
// into it, one file per material named after it.
#include <filesystem>
#include <string>
#include <vector>

#include "scene/material.h"

namespace gloss {

struct LibraryMaterial {
  std::string name;  // the material's name in its file
  Material material;
  std::string file;  // the file's name within the folder
};

// data_dir() / "materials" (config_paths.h), created when missing.
std::filesystem::path library_folder();

// Every material of the folder's .json and .mtl files, files in name order, materials in file
// order. A file that cannot be read adds "FILE: reason" to errors and is skipped; a missing
// folder is an empty library.
std::vector<LibraryMaterial> read_library(const std::filesystem::path& folder,
                                          std::vector<std::string>* errors = nullptr);

// Saves material as folder/<name>.json (file_defaults.h's file_name_for), replacing that file
// when it exists (the library's copy of the material is updated), atomically. Returns the path.
// Throws RuntimeFailure when it cannot be written.
std::string save_to_library(const std::filesystem::path& folder, const std::string& name,
                            const Material& material);

}  // namespace gloss
