#include "base/assets.h"

#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace gloss {

namespace {

namespace fs = std::filesystem;

// PREFIX/share/... for the executable at PREFIX/bin. Without /proc (not Linux), the working
// directory stands in for the executable's folder.
fs::path installed_share_path(const char* relative) {
  std::error_code exe_error;
  const fs::path exe = fs::read_symlink("/proc/self/exe", exe_error);
  const fs::path bin_dir = exe_error ? fs::path(".") : exe.parent_path();
  return (bin_dir / ".." / "share" / relative).lexically_normal();
}

bool is_folder(const fs::path& path) {
  std::error_code error;
  return fs::is_directory(path, error);
}

// The installed folder when it exists, else the source tree's (a build tree), else the
// installed one: a missing file is then reported where an installed program looks for it.
std::string installed_or_source(const char* installed, const char* source) {
  const fs::path beside_exe = installed_share_path(installed);
  if (is_folder(beside_exe)) return beside_exe.string();
  if (source != nullptr && is_folder(source)) return source;
  return beside_exe.string();
}

}  // namespace

std::string asset_dir() {
  const char* from_environment = std::getenv("GLOSS_ASSETS");
  if (from_environment != nullptr && from_environment[0] != '\0') return from_environment;
#ifdef GLOSS_SOURCE_ASSET_DIR
  return installed_or_source("gloss/assets", GLOSS_SOURCE_ASSET_DIR);
#else
  return installed_or_source("gloss/assets", nullptr);
#endif
}

std::string asset_path(const std::string& relative) {
  return asset_dir() + "/" + relative;
}

std::string doc_dir() {
#ifdef GLOSS_SOURCE_DOC_DIR
  return installed_or_source("doc/gloss", GLOSS_SOURCE_DOC_DIR);
#else
  return installed_or_source("doc/gloss", nullptr);
#endif
}

std::string doc_path(const std::string& relative) {
  return doc_dir() + "/" + relative;
}

}  // namespace gloss
