#pragma once
// Reading an EXR back with OpenEXR itself (not through gloss's writer), so a round trip checks
// what another program would read: the R, G and B channels as floats, and the file's compression.
#include <string>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>

#include "base/image.h"

namespace gloss::test {

struct ExrFile {
  Image image;
  Imf::Compression compression = Imf::NO_COMPRESSION;
  bool float_channels = false;  // R, G and B are all 32-bit float
};

inline ExrFile read_exr_file(const std::string& path) {
  Imf::InputFile file(path.c_str());
  const Imath::Box2i window = file.header().dataWindow();
  const int w = window.max.x - window.min.x + 1, h = window.max.y - window.min.y + 1;
  ExrFile out;
  out.image = Image(w, h);
  out.compression = file.header().compression();
  out.float_channels = true;
  for (const char* name : {"R", "G", "B"}) {
    const Imf::Channel* channel = file.header().channels().findChannel(name);
    out.float_channels = out.float_channels && channel != nullptr && channel->type == Imf::FLOAT;
  }
  char* base = reinterpret_cast<char*>(out.image.pixels.data()) -
               (static_cast<std::ptrdiff_t>(window.min.y) * w + window.min.x) * sizeof(glm::vec3);
  const std::size_t xs = sizeof(glm::vec3), ys = xs * static_cast<std::size_t>(w);
  Imf::FrameBuffer frame;
  frame.insert("R", Imf::Slice(Imf::FLOAT, base, xs, ys));
  frame.insert("G", Imf::Slice(Imf::FLOAT, base + sizeof(float), xs, ys));
  frame.insert("B", Imf::Slice(Imf::FLOAT, base + 2 * sizeof(float), xs, ys));
  file.setFrameBuffer(frame);
  file.readPixels(window.min.y, window.max.y);
  return out;
}

}  // namespace gloss::test
