// libFuzzer target: reading a PNG with its text chunks (io/image/image_io.h, read_png), the
// metadata path of gloss's renders: the CLI and the editor embed the scene as the `gloss:scene`
// text chunk, so a scene found there goes through the scene reader as any reader of that metadata
// would.
#include <cstdint>
#include <string>

#include "base/error.h"
#include "fuzz_input.h"
#include "io/image/image_io.h"
#include "io/scene/scene_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = gloss_fuzz::write_file("image.png", data, size);
  try {
    const gloss::Png8 png = gloss::read_png(path);
    for (const auto& [key, text] : png.text) {
      if (key == "gloss:scene") gloss::parse_scene(text, path);
    }
  } catch (const gloss::InputError&) {
  }
  return 0;
}
