// read_image_bytes (image_reader.h): an image held in memory, read by the same readers as files.
// The bytes go into an anonymous in-memory file (memfd_create) that the readers open by its
// /proc/self/fd name, so every format keeps one reader and its checks; messages name the image
// as the caller does.
#include <sys/mman.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include "base/error.h"
#include "io/image/image_reader.h"

namespace gloss {

FloatImage read_image_bytes(const std::string& bytes, const std::string& name,
                            const ImageReadOptions& options, ImageFileInfo* info) {
  const int fd = memfd_create("gloss-image", MFD_CLOEXEC);
  if (fd < 0)
    throw RuntimeFailure("cannot hold an image in memory: " + std::string(strerror(errno)));
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      throw RuntimeFailure("cannot hold an image in memory: " + std::string(strerror(errno)));
    }
    done += static_cast<std::size_t>(n);
  }
  const std::string path = "/proc/self/fd/" + std::to_string(fd);
  try {
    return read_image(path, options, info);
  } catch (const InputError& error) {
    std::string message = error.message();
    for (std::size_t at = message.find(path); at != std::string::npos;
         at = message.find(path, at + name.size())) {
      message.replace(at, path.size(), name);
    }
    throw InputError(name, message);
  }
}

}  // namespace gloss
