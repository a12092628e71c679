#pragma once
// The environment's prefiltered levels and the map itself packed into one RGB float image, as
// shaders/environment.glsl reads them (gloss_env_atlas, gloss_env_level): the raster path
// uploads it as a texture, Export GLSL writes it beside the shader. GL-free.
#include <vector>

#include <glm/vec4.hpp>

#include "base/image.h"
#include "engine/environment/prefiltered_environment.h"

namespace gloss {

struct EnvironmentAtlas {
  Image image;
  // (x, y, width, height) of each level in image, then of the map itself: kLevels + 1 entries.
  std::vector<glm::ivec4> levels;
};

// The map at the top left, the levels on shelves below it, each a texel apart.
EnvironmentAtlas make_environment_atlas(const PrefilteredEnvironment& maps);

}  // namespace gloss
