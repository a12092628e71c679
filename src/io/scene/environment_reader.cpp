#include "io/scene/environment_reader.h"

#include <algorithm>
#include <cstdio>

#include "base/text/number_text.h"
#include "io/image/image_reader.h"
#include "scene/memory/memory_estimate.h"

namespace gloss {

std::uint64_t environment_extra_bytes_per_texel() {
  return kEnvironmentBytesPerTexel;
}

std::shared_ptr<const EnvironmentMap> read_environment_map(const std::string& path,
                                                           std::uint64_t budget_bytes,
                                                           std::vector<std::string>* warnings) {
  ImageReadOptions options;
  options.data = ImageData::colour;
  options.budget_bytes = budget_bytes;
  options.extra_bytes_per_pixel = environment_extra_bytes_per_texel();
  FloatImage image = read_image(path, options);
  auto map = std::make_shared<EnvironmentMap>();
  map->source = path;
  map->radiance = Image(image.width, image.height);
  const int c = image.channels;
  long long negative = 0;
  float lowest = 0.0f;
  double sum = 0.0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      glm::vec3 rgb = c >= 3 ? glm::vec3(image.at(x, y, 0), image.at(x, y, 1), image.at(x, y, 2))
                             : glm::vec3(image.at(x, y, 0));
      for (int k = 0; k < 3; ++k) {
        if (rgb[k] < 0.0f) {
          ++negative;
          lowest = std::min(lowest, rgb[k]);
          rgb[k] = 0.0f;
        }
      }
      map->radiance.at(x, y) = rgb;
      sum += double(rgb.x) + rgb.y + rgb.z;
    }
  }
  // Said only when they matter: below -1 % of the map's mean radiance (the shipped studio
  // lights' DWAB noise stays under 0.6 % of theirs).
  const double mean = sum / (3.0 * static_cast<double>(map->radiance.pixels.size()));
  if (negative > 0 && warnings != nullptr && -lowest > 0.01 * mean) {
    warnings->push_back(path + ": " + std::to_string(negative) + " negative samples (down to " +
                        number_text(lowest) + ") read as 0: radiance is never negative");
  }
  return map;
}

}  // namespace gloss
