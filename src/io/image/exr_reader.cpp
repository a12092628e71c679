// read_exr_image (map_readers.h): OpenEXR through the OpenEXR library (scan lines or tiles,
// every compression it has, DWAB included: Blender's studio lights). The first part's R, G, B
// (and A) channels, or Y (and A) for a grey image, as 32-bit floats whatever they are stored as.
// The headers are walked first (exr_header_scan.h): the library allocates what a header declares.
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>

#include <algorithm>
#include <exception>
#include <functional>
#include <mutex>
#include <string>
#include <vector>

#include "base/error.h"
#include "io/image/exr_header_scan.h"
#include "io/image/map_readers.h"

namespace gloss {

namespace {

// The channels a map takes: R, G and B, or Y for a grey image, then A when there is one.
std::vector<const char*> map_channels(const std::string& path,
                                      const std::function<bool(const char*)>& has) {
  const bool rgb = has("R") && has("G") && has("B");
  if (!rgb && !has("Y")) {
    throw InputError(path, "OpenEXR image has neither R, G and B channels nor a Y channel");
  }
  std::vector<const char*> names =
      rgb ? std::vector<const char*>{"R", "G", "B"} : std::vector<const char*>{"Y"};
  if (has("A")) names.push_back("A");
  return names;
}

}  // namespace

FloatImage read_exr_image(const std::string& path, const ImageReadOptions& options,
                          ImageFileInfo& info) {
  info.format = "OpenEXR";
  // Before the library reads the file: its headers' structure, and the floats with the library's
  // own buffers against the budget.
  const ExrHeaderScan scan = scan_exr_header(path);
  const auto scanned = map_channels(path, [&](const char* name) {
    return std::find(scan.channels.begin(), scan.channels.end(), name) != scan.channels.end();
  });
  check_image_size(path, "OpenEXR", scan.width, scan.height, static_cast<int>(scanned.size()),
                   options, scan.library_bytes);
  // OpenEXR refuses a larger header while it reads it, before anything is allocated for it.
  // The limits are the library's process-wide settings: set once, not by every read (two maps
  // read at once would race on them).
  static std::once_flag limits_set;
  std::call_once(limits_set, [] {
    Imf::Header::setMaxImageSize(kMaxMapSide, kMaxMapSide);
    Imf::Header::setMaxTileSize(kMaxMapSide, kMaxMapSide);
  });
  try {
    Imf::InputFile file(path.c_str());
    const Imf::Header& header = file.header();
    const Imath::Box2i window = header.dataWindow();
    const long long width = static_cast<long long>(window.max.x) - window.min.x + 1;
    const long long height = static_cast<long long>(window.max.y) - window.min.y + 1;
    const Imf::ChannelList& list = header.channels();
    const std::vector<const char*> names =
        map_channels(path, [&](const char* name) { return list.findChannel(name) != nullptr; });
    const int channels = static_cast<int>(names.size());
    for (const char* name : names) {
      const Imf::Channel* c = list.findChannel(name);
      if (c->xSampling != 1 || c->ySampling != 1) {
        throw InputError(path, std::string("OpenEXR channel ") + name +
                                   " is subsampled; gloss reads full-resolution channels");
      }
      info.bits = std::max(info.bits, c->type == Imf::HALF ? 16 : 32);
    }
    // Again from the library's reading of the header, which sizes the floats allocated here.
    check_image_size(path, "OpenEXR", width, height, channels, options);

    FloatImage image;
    image.width = static_cast<int>(width);
    image.height = static_cast<int>(height);
    image.channels = channels;
    image.samples.assign(static_cast<std::size_t>(width) * height * channels, 0.0f);
    Imf::FrameBuffer frame;
    const std::size_t x_stride = sizeof(float) * channels;
    for (int c = 0; c < channels; ++c) {
      frame.insert(names[static_cast<std::size_t>(c)],
                   Imf::Slice::Make(Imf::FLOAT, image.samples.data() + c, window, x_stride,
                                    x_stride * static_cast<std::size_t>(width)));
    }
    file.setFrameBuffer(frame);
    if (!file.isComplete()) {
      throw InputError(path,
                       "invalid OpenEXR: the file is truncated (some of its pixel data "
                       "is missing)");
    }
    file.readPixels(window.min.y, window.max.y);
    return image;
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& error) {
    // Iex's messages can span lines; the first says what went wrong.
    std::string message = error.what();
    message = message.substr(0, message.find('\n'));
    throw InputError(path, "invalid OpenEXR: " + message);
  }
}

}  // namespace gloss
