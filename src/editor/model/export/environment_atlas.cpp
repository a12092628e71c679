#include "editor/model/export/environment_atlas.h"

#include <algorithm>

namespace gloss {

EnvironmentAtlas make_environment_atlas(const PrefilteredEnvironment& maps) {
  const Image& source = maps.image(maps.levels());
  const int width = std::max(source.width, 256);
  // Shelves: levels left to right, a new shelf when one is full.
  std::vector<glm::ivec4> placed;
  int x = 0, y = source.height + 1, shelf = 0;
  for (int k = 0; k < maps.levels(); ++k) {
    const Image& level = maps.image(k);
    if (x + level.width > width) {
      x = 0;
      y += shelf + 1;
      shelf = 0;
    }
    placed.emplace_back(x, y, level.width, level.height);
    x += level.width + 1;
    shelf = std::max(shelf, level.height);
  }
  EnvironmentAtlas atlas;
  atlas.image = Image(width, y + shelf);
  auto copy = [&](const Image& from, int at_x, int at_y) {
    for (int j = 0; j < from.height; ++j) {
      for (int i = 0; i < from.width; ++i) atlas.image.at(at_x + i, at_y + j) = from.at(i, j);
    }
  };
  for (int k = 0; k < maps.levels(); ++k) copy(maps.image(k), placed[k].x, placed[k].y);
  copy(source, 0, 0);
  atlas.levels = placed;
  atlas.levels.emplace_back(0, 0, source.width, source.height);
  return atlas;
}

}  // namespace gloss
