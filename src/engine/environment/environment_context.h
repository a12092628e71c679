#pragma once
// What the environment's stages read besides the scene (engine's own): the prefiltered maps,
// the rotation, and per material the exponent its specular level stands for and which terms it
// has, made once per version of the document.
#include <cstdint>
#include <memory>
#include <vector>

#include "engine/environment/environment_sampling.h"
#include "engine/environment/prefiltered_environment.h"
#include "scene/scene.h"
#include "shading/environment.h"

namespace gloss {

struct EnvironmentContext {
  std::shared_ptr<const PrefilteredEnvironment> maps;  // null: no environment planned
  std::shared_ptr<const EnvironmentSampler> sampler;   // the map's draws (env_samples > 0)
  EnvironmentRotation<float> rotation;
  EnvironmentRotation<double> rotation_d;
  // Per material (entry 0 stands in when there are none).
  std::vector<float> exponent;                     // phong_equivalent_exponent
  std::vector<std::uint8_t> diffuse, specular;     // kd, ks not zero
  std::vector<std::int32_t> object_material;       // per object
};

// The tables for scene; planned: the render plan has the environment (else an empty context).
EnvironmentContext make_environment_context(const Scene& scene, bool planned);

}  // namespace gloss
