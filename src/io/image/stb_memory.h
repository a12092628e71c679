#pragma once
// Reading a file's bytes through stb_image's callbacks (io's own, private): stb reads past the
// end of a truncated file as zeros without an error, but it asks its callbacks for more when it
// does, which is how a truncated file is told from a whole one (the HDR reader).
#include <cstddef>
#include <string>
#include <vector>

#include <stb_image.h>

#include "io/image/image_reader.h"

namespace gloss {

struct StbMemory {
  const std::vector<stbi_uc>* bytes = nullptr;
  std::size_t at = 0;
  bool ran_out = false;  // stb asked for bytes after the last one

  explicit StbMemory(const std::vector<stbi_uc>& b) : bytes(&b) {}
  // The callbacks that read from this (user data: a StbMemory).
  static const stbi_io_callbacks& callbacks();
};

// The whole file, refused (naming `format`) when it alone exceeds the budget of options or 2 GB
// (stb's sizes are ints). Throws InputError naming path.
std::vector<stbi_uc> read_file_bytes(const std::string& path, const char* format,
                                     const ImageReadOptions& options);

}  // namespace gloss
