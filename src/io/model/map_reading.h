#pragma once
// What the OBJ and glTF map readers of model_maps.h share (io's own, private): the budget the
// model's maps are read against, the images they name read into textures with every failure a
// warning, and textures made per texel from others.
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include <glm/vec4.hpp>

#include "io/model/model_loader.h"

namespace gloss {

struct ModelMapReader {
  std::string model_path;  // the model file, for messages and references
  std::string model_dir;   // its folder; "" for the current one
  Model& model;
  std::uint64_t budget = 0;  // bytes the maps may take
  std::uint64_t used = 0;    // bytes read so far (not counting textures already in memory)

  // A reason a material's map cannot be used: a warning, and a line of the editor's notice.
  void unusable(const std::string& material, const std::string& what);

  // The image at path (relative to the model's folder) as colour or data; null, with the reason
  // reported for material, when it cannot be read. An image missing where the model says looks
  // for the same name in the model's own folder (files written with absolute paths elsewhere).
  std::shared_ptr<const Texture> read_file(const std::string& material, const std::string& path,
                                           bool colour, std::string& used_path);

  // An image inside the file ("*N"), decoded as colour or data; null (reported) when it cannot.
  std::shared_ptr<const Texture> read_embedded(const std::string& material, const std::string& name,
                                               bool colour);

  // A texture of w x h texels with `channels` (1 or 4) made by texel(u, v) at each texel centre
  // (map coordinates); null (reported) when it does not fit the budget.
  std::shared_ptr<const Texture> make(const std::string& material, const std::string& what,
                                      int width, int height, int channels,
                                      const std::function<glm::vec4(float, float)>& texel);
};

// The maps of an OBJ file's materials (its MTL files) and of a glTF file's (as assimp lists
// them), set on reader.model's materials.
void read_obj_maps(ModelMapReader& reader);
void read_gltf_maps(ModelMapReader& reader);

}  // namespace gloss
