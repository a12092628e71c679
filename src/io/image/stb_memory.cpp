#include "io/image/stb_memory.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>

#include "base/error.h"
#include "io/image/map_readers.h"

namespace gloss {

namespace {

int read_bytes(void* user, char* out, int size) {
  auto& r = *static_cast<StbMemory*>(user);
  const std::size_t n = std::min(static_cast<std::size_t>(size), r.bytes->size() - r.at);
  std::memcpy(out, r.bytes->data() + r.at, n);
  r.at += n;
  if (n == 0 && size > 0) r.ran_out = true;
  return static_cast<int>(n);
}

void skip_bytes(void* user, int n) {
  auto& r = *static_cast<StbMemory*>(user);
  if (n < 0) {
    r.at -= std::min(r.at, static_cast<std::size_t>(-static_cast<long long>(n)));
  } else {
    r.at = std::min(r.bytes->size(), r.at + static_cast<std::size_t>(n));
  }
}

int at_end(void* user) {
  const auto& r = *static_cast<const StbMemory*>(user);
  return r.at >= r.bytes->size() ? 1 : 0;
}

}  // namespace

const stbi_io_callbacks& StbMemory::callbacks() {
  static const stbi_io_callbacks functions = {read_bytes, skip_bytes, at_end};
  return functions;
}

std::vector<stbi_uc> read_file_bytes(const std::string& path, const char* format,
                                     const ImageReadOptions& options) {
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"),
                                                       &std::fclose);
  if (!file) throw InputError(path, std::string("cannot read: ") + std::strerror(errno));
  std::fseek(file.get(), 0, SEEK_END);
  const long size = std::ftell(file.get());
  std::fseek(file.get(), 0, SEEK_SET);
  if (size < 0) throw InputError(path, std::string("cannot read: ") + std::strerror(errno));
  if (static_cast<std::uint64_t>(size) > image_budget(options) ||
      size > std::numeric_limits<int>::max()) {
    throw InputError(path, std::string(format) + " file of " + std::to_string(size) +
                               " bytes is larger than the memory budget allows");
  }
  std::vector<stbi_uc> bytes(static_cast<std::size_t>(size));
  if (std::fread(bytes.data(), 1, bytes.size(), file.get()) != bytes.size()) {
    throw InputError(path, std::string("cannot read: ") + std::strerror(errno));
  }
  return bytes;
}

}  // namespace gloss
