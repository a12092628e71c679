// read_exr_image (map_readers.h): OpenEXR through the OpenEXR library (scan lines or tiles,
// every compression it has, DWAB included: Blender's studio lights). The first part's R, G, B
// (and A) channels, or Y (and A) for a grey image, as 32-bit floats whatever they are stored as.
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfTestFile.h>

#include <exception>
#include <string>
#include <vector>

#include "base/error.h"
#include "io/image/map_readers.h"

namespace gloss {

FloatImage read_exr_image(const std::string& path, const ImageReadOptions& options,
                          ImageFileInfo& info) {
  info.format = "OpenEXR";
  // OpenEXR refuses a larger header while it reads it, before anything is allocated for it.
  Imf::Header::setMaxImageSize(kMaxMapSide, kMaxMapSide);
  Imf::Header::setMaxTileSize(kMaxMapSide, kMaxMapSide);
  try {
    bool tiled = false, deep = false, multipart = false;
    if (!Imf::isOpenExrFile(path.c_str(), tiled, deep, multipart)) {
      throw InputError(path, "invalid OpenEXR: not an OpenEXR file");
    }
    if (deep) throw InputError(path, "OpenEXR deep images are not maps");
    Imf::InputFile file(path.c_str());
    const Imf::Header& header = file.header();
    const Imath::Box2i window = header.dataWindow();
    const long long width = static_cast<long long>(window.max.x) - window.min.x + 1;
    const long long height = static_cast<long long>(window.max.y) - window.min.y + 1;
    const Imf::ChannelList& list = header.channels();
    const bool rgb = list.findChannel("R") != nullptr && list.findChannel("G") != nullptr &&
                     list.findChannel("B") != nullptr;
    const bool grey = !rgb && list.findChannel("Y") != nullptr;
    if (!rgb && !grey) {
      throw InputError(path, "OpenEXR image has neither R, G and B channels nor a Y channel");
    }
    const bool alpha = list.findChannel("A") != nullptr;
    std::vector<const char*> names = rgb ? std::vector<const char*>{"R", "G", "B"}
                                         : std::vector<const char*>{"Y"};
    if (alpha) names.push_back("A");
    const int channels = static_cast<int>(names.size());
    for (const char* name : names) {
      const Imf::Channel* c = list.findChannel(name);
      if (c->xSampling != 1 || c->ySampling != 1) {
        throw InputError(path, std::string("OpenEXR channel ") + name +
                                   " is subsampled; gloss reads full-resolution channels");
      }
      info.bits = std::max(info.bits, c->type == Imf::HALF ? 16 : 32);
    }
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
      throw InputError(path, "invalid OpenEXR: the file is truncated (some of its pixel data "
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
