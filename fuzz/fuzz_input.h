#pragma once
// What every fuzz target shares: a private temporary folder for loaders that take a path, and the
// rule that decides what is a finding. The readers' contract (docs/spec/scene-and-cli.md) is that
// bad input ends in an InputError; any other exception escaping a reader is a finding, so the
// targets catch InputError only and let libFuzzer report the rest (an uncaught exception aborts).
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace gloss_fuzz {

// A folder of this process's own, removed at exit: several fuzzers (and fork-mode jobs) may run
// at once, so no fixed name.
inline const std::filesystem::path& temp_dir() {
  static const std::filesystem::path dir = [] {
    std::string pattern = (std::filesystem::temp_directory_path() / "gloss-fuzz-XXXXXX").string();
    if (mkdtemp(pattern.data()) == nullptr) {
      std::perror("gloss-fuzz: mkdtemp");
      std::abort();
    }
    std::atexit([] {
      std::error_code ignored;
      std::filesystem::remove_all(temp_dir(), ignored);
    });
    return std::filesystem::path(pattern);
  }();
  return dir;
}

// Writes bytes to name inside temp_dir() and returns its path (the readers take paths).
inline std::string write_file(const std::string& name, const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path path = temp_dir() / name;
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (file == nullptr || std::fwrite(data, 1, size, file) != size || std::fclose(file) != 0) {
    std::perror("gloss-fuzz: writing the input");
    std::abort();
  }
  return path.string();
}

inline std::string write_file(const std::string& name, const std::string& text) {
  return write_file(name, reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
}

}  // namespace gloss_fuzz
