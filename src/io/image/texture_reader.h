#pragma once
// Map files read as textures (texture/texture.h): any image image_reader.h reads, decoded as
// colour (sRGB-decoded unless the file says linear) or as data (linear), then its mip pyramid
// built (texture/mip_pyramid.h). The pyramid is counted against the budget with the decoded
// samples before anything is allocated. Textures are shared: reading the same file (same
// contents on disk) for the same use again gives the texture already in memory while any scene
// still holds it, so undo copies, reopened scenes and maps named twice cost nothing more.
#include <cstdint>
#include <memory>
#include <string>

#include "base/float_image.h"
#include "io/image/image_reader.h"
#include "texture/texture.h"

namespace gloss {

// Bytes per texel a map's pyramid takes beside its decoded samples, at most: level 0 in RGBA
// float (16) and the levels below it (at most as much again, for a strip), counted against the
// budget before a map is read.
constexpr std::uint64_t kPyramidBytesPerTexel = 32;

// Bytes a map of w x h texels with `channels` samples per texel holds as a texture.
std::uint64_t texture_bytes_for(int width, int height, int channels);

// Reads path as colour or data against budget_bytes (0: the memory budget). Throws InputError
// naming path. *cached is set when the texture came from the cache (its bytes were counted when
// it was first read).
std::shared_ptr<const Texture> read_texture(const std::string& path, ImageData data,
                                            std::uint64_t budget_bytes = 0, bool* cached = nullptr);

// A texture of an image already decoded (a model's embedded or converted map), not cached.
std::shared_ptr<const Texture> texture_from_image(FloatImage image, const std::string& source,
                                                  const ImageFileInfo& info);

}  // namespace gloss
