#include "editor/model/session/config_paths.h"

#include <cstdlib>
#include <system_error>

namespace gloss {

namespace {

std::filesystem::path xdg_dir(const char* variable, const char* home_relative) {
  std::filesystem::path dir;
  const char* xdg = std::getenv(variable);
  const char* home = std::getenv("HOME");
  // The XDG spec ignores relative values.
  if (xdg != nullptr && xdg[0] == '/') {
    dir = std::filesystem::path(xdg) / "gloss";
  } else if (home != nullptr && home[0] != '\0') {
    dir = std::filesystem::path(home) / home_relative / "gloss";
  } else {
    dir = std::filesystem::temp_directory_path() / "gloss";
  }
  std::error_code ignored;  // a folder that cannot be made shows up as a failed write later
  std::filesystem::create_directories(dir, ignored);
  return dir;
}

}  // namespace

std::filesystem::path config_dir() {
  return xdg_dir("XDG_CONFIG_HOME", ".config");
}

std::filesystem::path state_dir() {
  return xdg_dir("XDG_STATE_HOME", ".local/state");
}

}  // namespace gloss
