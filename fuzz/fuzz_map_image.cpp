// libFuzzer target: the map readers (io/image/image_reader.h, read_image) on one format's files:
// PNG of every colour type and depth, Radiance HDR (stb_image, truncation checked), OpenEXR
// (the OpenEXR library) or JPEG (stb_image, baseline and progressive). read_image picks the reader
// from the first bytes, so each target's seeds decide what it mostly explores; GLOSS_FUZZ_EXTENSION
// names the file it writes. The memory budget is 256 MB, so a header claiming a huge image must be
// refused before it is allocated (the fuzzer's limit is 512 MB for one allocation).
#include <cstdint>
#include <string>

#include "base/error.h"
#include "fuzz_input.h"
#include "io/image/image_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path =
      gloss_fuzz::write_file(std::string("map") + GLOSS_FUZZ_EXTENSION, data, size);
  gloss::ImageReadOptions options;
  options.budget_bytes = std::uint64_t(256) << 20;
  for (gloss::ImageData kind : {gloss::ImageData::colour, gloss::ImageData::linear}) {
    options.data = kind;
    try {
      const gloss::FloatImage image = gloss::read_image(path, options);
      if (image.samples.size() != std::size_t(image.width) * image.height * image.channels) {
        __builtin_trap();  // the reader's own promise
      }
    } catch (const gloss::InputError&) {
    }
  }
  return 0;
}
