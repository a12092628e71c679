#include "base/assets.h"

#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace gloss {

std::string asset_dir() {
  const char* from_environment = std::getenv("GLOSS_ASSETS");
  if (from_environment != nullptr && from_environment[0] != '\0') return from_environment;

#ifdef GLOSS_SOURCE_ASSET_DIR
  // Running from a build tree: the source checkout's assets/, when it is still there.
  std::error_code error;
  if (std::filesystem::is_directory(GLOSS_SOURCE_ASSET_DIR, error)) return GLOSS_SOURCE_ASSET_DIR;
#endif

  // Installed layout: PREFIX/bin/gloss and PREFIX/share/gloss/assets. Without /proc (not Linux),
  // the working directory stands in for the executable's folder.
  std::error_code exe_error;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", exe_error);
  const std::filesystem::path bin_dir = exe_error ? std::filesystem::path(".") : exe.parent_path();
  return (bin_dir / ".." / "share" / "gloss" / "assets").lexically_normal().string();
}

std::string asset_path(const std::string& relative) {
  return asset_dir() + "/" + relative;
}

}  // namespace gloss
