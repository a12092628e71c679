#include "editor/model/session/config_paths.h"

#include <cstdlib>
#include <fstream>
#include <string>
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

std::filesystem::path data_dir() {
  return xdg_dir("XDG_DATA_HOME", ".local/share");
}

// Read by hand: user-dirs.dirs is a list of KEY="VALUE" lines where VALUE is "$HOME/..." or an
// absolute path (the xdg-user-dirs format); GLib's g_get_user_special_dir reads the same file,
// and linking GLib for one lookup is not worth it.
std::filesystem::path documents_dir() {
  namespace fs = std::filesystem;
  const char* home_env = std::getenv("HOME");
  const std::string home = home_env != nullptr ? home_env : "";
  const char* config = std::getenv("XDG_CONFIG_HOME");
  const fs::path dirs = config != nullptr && config[0] == '/'
                            ? fs::path(config) / "user-dirs.dirs"
                            : fs::path(home) / ".config" / "user-dirs.dirs";
  std::error_code ec;
  std::ifstream in(dirs);
  for (std::string line; std::getline(in, line);) {
    const std::string key = "XDG_DOCUMENTS_DIR=\"";
    if (line.rfind(key, 0) != 0) continue;
    std::string value = line.substr(key.size());
    value = value.substr(0, value.find('"'));
    if (value.rfind("$HOME", 0) == 0) value = home + value.substr(5);
    if (!value.empty() && value[0] == '/' && fs::is_directory(value, ec)) return value;
  }
  if (!home.empty() && fs::is_directory(fs::path(home) / "Documents", ec)) {
    return fs::path(home) / "Documents";
  }
  if (!home.empty() && fs::is_directory(home, ec)) return home;
  return fs::current_path(ec);
}

}  // namespace gloss
