#include "io/image/exr_writer.h"

#include <cerrno>
#include <cstdio>
#include <exception>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfOutputFile.h>

#include "base/atomic_file.h"
#include "base/error.h"

namespace gloss {

namespace {

// OpenEXR's output through the stdio stream write_stream_atomically hands out, so the file gets
// its name only once complete. OpenEXR seeks back to fill in its line offset table.
class StdioStream : public Imf::OStream {
 public:
  StdioStream(std::FILE* file, const std::string& path)
      : Imf::OStream(path.c_str()), m_file(file) {}
  void write(const char c[], int n) override {
    if (std::fwrite(c, 1, static_cast<std::size_t>(n), m_file) != static_cast<std::size_t>(n)) {
      throw_write_error(fileName(), errno != 0 ? errno : EIO);
    }
  }
  uint64_t tellp() override {
    const long at = std::ftell(m_file);
    if (at < 0) throw_write_error(fileName(), errno);
    return static_cast<uint64_t>(at);
  }
  void seekp(uint64_t pos) override {
    if (std::fseek(m_file, static_cast<long>(pos), SEEK_SET) != 0) {
      throw_write_error(fileName(), errno);
    }
  }

 private:
  std::FILE* m_file;
};

}  // namespace

void write_exr(const std::string& path, const Image& image) {
  if (image.width <= 0 || image.height <= 0 ||
      image.pixels.size() != static_cast<std::size_t>(image.width) * image.height) {
    throw RuntimeFailure("cannot write " + path + ": the image has no pixels or the wrong count");
  }
  write_stream_atomically(path, [&](std::FILE* file) {
    try {
      Imf::Header header(image.width, image.height);
      header.compression() = Imf::ZIP_COMPRESSION;
      for (const char* name : {"R", "G", "B"}) {
        header.channels().insert(name, Imf::Channel(Imf::FLOAT));
      }
      // The image's floats in place: x, y, z of each glm::vec3, rows top first.
      char* base = reinterpret_cast<char*>(const_cast<glm::vec3*>(image.pixels.data()));
      const std::size_t x_stride = sizeof(glm::vec3);
      const std::size_t y_stride = x_stride * static_cast<std::size_t>(image.width);
      Imf::FrameBuffer frame;
      frame.insert("R", Imf::Slice(Imf::FLOAT, base, x_stride, y_stride));
      frame.insert("G", Imf::Slice(Imf::FLOAT, base + sizeof(float), x_stride, y_stride));
      frame.insert("B", Imf::Slice(Imf::FLOAT, base + 2 * sizeof(float), x_stride, y_stride));
      StdioStream stream(file, path);
      Imf::OutputFile out(stream, header);
      out.setFrameBuffer(frame);
      out.writePixels(image.height);
    } catch (const RuntimeFailure&) {
      throw;
    } catch (const std::exception& e) {  // OpenEXR's Iex exceptions
      throw RuntimeFailure("cannot write " + path + ": " + e.what());
    }
  });
}

}  // namespace gloss
