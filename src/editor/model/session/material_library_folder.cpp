#include "editor/model/session/material_library_folder.h"

#include <algorithm>
#include <system_error>

#include "base/text/ascii.h"
#include "editor/model/session/config_paths.h"
#include "editor/model/session/file_defaults.h"
#include "io/material/material_io.h"

namespace gloss {

namespace {}  // namespace

std::filesystem::path library_folder() {
  const std::filesystem::path folder = data_dir() / "materials";
  std::error_code ignored;  // a folder that cannot be made shows up when saving into it
  std::filesystem::create_directories(folder, ignored);
  return folder;
}

std::vector<LibraryMaterial> read_library(const std::filesystem::path& folder,
                                          std::vector<std::string>* errors) {
  std::vector<std::filesystem::path> files;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
    const std::string ext = lower_extension(entry.path());
    const std::string name = entry.path().filename().string();
    if ((ext == ".json" || ext == ".mtl") && !name.empty() && name[0] != '.') {
      files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  std::vector<LibraryMaterial> out;
  for (const std::filesystem::path& file : files) {
    try {
      const std::vector<NamedMaterial> materials = lower_extension(file) == ".mtl"
                                                       ? load_mtl(file.string())
                                                       : load_materials_json(file.string());
      for (const NamedMaterial& m : materials) {
        out.push_back({m.first, m.second, file.filename().string()});
      }
    } catch (const std::exception& e) {
      if (errors != nullptr) errors->push_back(e.what());
    }
  }
  return out;
}

std::string save_to_library(const std::filesystem::path& folder, const std::string& name,
                            const Material& material) {
  std::error_code ignored;
  std::filesystem::create_directories(folder, ignored);
  const std::string path = (folder / file_name_for(name, ".json")).string();
  save_materials_json(path, {{name, material}});
  return path;
}

}  // namespace gloss
