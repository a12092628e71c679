#include "io/image/texture_reader.h"

#include <sys/stat.h>

#include <filesystem>
#include <map>
#include <mutex>
#include <tuple>
#include <utility>

#include "texture/mip_pyramid.h"

namespace gloss {

namespace {

// What makes two reads the same: the file (by its absolute, normalised path), its size and
// modification time (a file painted over since gives a new texture), and the use.
struct CacheKey {
  std::string path;
  long long size = 0, modified_ns = 0;
  ImageData data = ImageData::colour;
  bool operator<(const CacheKey& o) const {
    return std::tie(path, size, modified_ns, data) <
           std::tie(o.path, o.size, o.modified_ns, o.data);
  }
};

std::mutex& cache_mutex() {
  static std::mutex m;
  return m;
}
std::map<CacheKey, std::weak_ptr<const Texture>>& cache() {
  static std::map<CacheKey, std::weak_ptr<const Texture>> c;
  return c;
}

bool key_of(const std::string& path, ImageData data, CacheKey& key) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return false;
  std::error_code error;
  const std::filesystem::path absolute = std::filesystem::absolute(path, error);
  if (error) return false;
  key.path = absolute.lexically_normal().string();
  key.size = static_cast<long long>(st.st_size);
  key.modified_ns = static_cast<long long>(st.st_mtim.tv_sec) * 1000000000LL + st.st_mtim.tv_nsec;
  key.data = data;
  return true;
}

}  // namespace

std::uint64_t texture_bytes_for(int width, int height, int channels) {
  return pyramid_bytes(width, height, stored_channels(channels));
}

std::shared_ptr<const Texture> texture_from_image(FloatImage image, const std::string& source,
                                                  const ImageFileInfo& info) {
  auto texture = std::make_shared<Texture>(make_texture(std::move(image)));
  texture->source = source;
  texture->format = info.format;
  texture->bits = info.bits;
  texture->srgb_decoded = info.srgb_decoded;
  return texture;
}

std::shared_ptr<const Texture> read_texture(const std::string& path, ImageData data,
                                            std::uint64_t budget_bytes, bool* cached) {
  if (cached != nullptr) *cached = false;
  CacheKey key;
  const bool keyed = key_of(path, data, key);
  if (keyed) {
    const std::lock_guard<std::mutex> lock(cache_mutex());
    // find, not operator[]: a miss whose read then fails must leave no empty entry behind.
    const auto found = cache().find(key);
    if (std::shared_ptr<const Texture> hit =
            found != cache().end() ? found->second.lock() : nullptr) {
      if (cached != nullptr) *cached = true;
      return hit;
    }
  }
  ImageReadOptions options;
  options.data = data;
  options.budget_bytes = budget_bytes;
  options.extra_bytes_per_pixel = kPyramidBytesPerTexel;
  ImageFileInfo info;
  FloatImage image = read_image(path, options, &info);
  std::shared_ptr<const Texture> texture = texture_from_image(std::move(image), path, info);
  if (keyed) {
    const std::lock_guard<std::mutex> lock(cache_mutex());
    auto& slot = cache()[key];
    if (std::shared_ptr<const Texture> other = slot.lock()) return other;  // read meanwhile
    slot = texture;
    for (auto it = cache().begin(); it != cache().end();) {  // forget textures no one holds
      it = it->second.expired() ? cache().erase(it) : std::next(it);
    }
  }
  return texture;
}

}  // namespace gloss
