#pragma once
// The raster path's environment: the ray tracer's prefiltered levels (the engine's shared
// PrefilteredEnvironment of the map, at the scene's env_resolution) packed into one RGB float
// texture (editor/model/export/environment_atlas.h), uploaded again only when the levels
// change, and the uniforms shaders/environment.glsl reads. Needs a current GL context.
#include <memory>
#include <vector>

#include <glad/gl.h>
#include <glm/vec4.hpp>

#include "editor/gl/gl_texture.h"
#include "engine/environment/prefiltered_environment.h"
#include "scene/scene.h"

namespace gloss {

class EnvironmentTexture {
 public:
  // Holds scene's environment's levels (the scene must have one).
  void update(const Scene& scene);
  // Binds the atlas to texture unit `unit` and sets program's environment uniforms (in use).
  void use(GLuint program, const Scene& scene, int unit) const;
  std::size_t bytes() const;

 private:
  std::shared_ptr<const PrefilteredEnvironment> m_maps;  // what the texture holds
  GlTexture m_texture;
  std::vector<glm::ivec4> m_levels;
};

}  // namespace gloss
