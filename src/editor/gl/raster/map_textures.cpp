#include "editor/gl/raster/map_textures.h"

#include <cmath>
#include <set>
#include <stdexcept>
#include <string>

#include "editor/gl/raster/raster_programs.h"

namespace gloss {

namespace {

GLuint upload(const Texture& texture) {
  GLuint name = 0;
  glGenTextures(1, &name);
  glBindTexture(GL_TEXTURE_2D, name);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  const bool grey = texture.channels == 1;
  for (int l = 0; l < texture.level_count(); ++l) {
    const MipLevel& level = texture.levels[static_cast<std::size_t>(l)];
    // Row 0 of the pyramid is the image's top row and becomes GL row 0: texelFetch's (i, j) is
    // the contract's texel (i, j), j from the top.
    glTexImage2D(GL_TEXTURE_2D, l, grey ? GL_R32F : GL_RGBA32F, level.width, level.height, 0,
                 grey ? GL_RED : GL_RGBA, GL_FLOAT, level.texels.data());
  }
  // texelFetch ignores filtering; the levels must still make a complete texture.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, texture.level_count() - 1);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  if (grey) {  // read as (g, g, g, 1), as texture_lookup.h's texel_at
    const GLint swizzle[4] = {GL_RED, GL_RED, GL_RED, GL_ONE};
    glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_RGBA, swizzle);
  }
  return name;
}

}  // namespace

MapTextures::MapTextures() {
  glGenTextures(1, &m_empty);
  glBindTexture(GL_TEXTURE_2D, m_empty);
  const float one[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, 1, 1, 0, GL_RGBA, GL_FLOAT, one);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

MapTextures::~MapTextures() {
  for (auto& [key, entry] : m_textures) glDeleteTextures(1, &entry.name);
  glDeleteTextures(1, &m_empty);
}

int MapTextures::sync(const Scene& scene) {
  std::set<const Texture*> used;
  int uploaded = 0;
  for (const Material& material : scene.materials) {
    for (int s = 0; s < kMapSlots; ++s) {
      const TextureMap& map = material.map(static_cast<MapSlot>(s));
      if (!map.present()) continue;
      used.insert(map.texture.get());
      if (m_textures.count(map.texture.get()) != 0) continue;
      m_textures.emplace(map.texture.get(), Entry{map.texture, upload(*map.texture)});
      ++uploaded;
    }
  }
  for (auto it = m_textures.begin(); it != m_textures.end();) {
    if (used.count(it->first) != 0) {
      ++it;
      continue;
    }
    glDeleteTextures(1, &it->second.name);
    it = m_textures.erase(it);
  }
  return uploaded;
}

GLuint MapTextures::texture(const Texture* texture) const {
  if (texture == nullptr) return m_empty;
  const auto found = m_textures.find(texture);
  if (found == m_textures.end()) throw std::logic_error("map textures: texture not synced");
  return found->second.name;
}

std::size_t MapTextures::bytes() const {
  std::size_t total = 16;
  for (const auto& [key, entry] : m_textures) total += entry.texture->bytes();
  return total;
}

void set_map_uniforms(GLuint program, const MapTextures& maps, const Material& material,
                      MapFilter filter, float cone_spread, int first_unit) {
  static const char* const samplers[kMapSlots] = {
      "gloss_map_diffuse",   "gloss_map_ambient", "gloss_map_specular", "gloss_map_emission",
      "gloss_map_shininess", "gloss_map_opacity", "gloss_map_normal",   "gloss_map_bump"};
  int present[kMapSlots], wrap[2 * kMapSlots], info[2 * kMapSlots], alpha[kMapSlots];
  float transform[4 * kMapSlots], offset[2 * kMapSlots];
  for (int s = 0; s < kMapSlots; ++s) {
    const TextureMap& map = material.map(static_cast<MapSlot>(s));
    glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(first_unit + s));
    glBindTexture(GL_TEXTURE_2D, maps.texture(map.texture.get()));
    set_uniform(program, samplers[s], first_unit + s);
    present[s] = map.present() ? 1 : 0;
    wrap[2 * s] = static_cast<int>(map.wrap[0]);
    wrap[2 * s + 1] = static_cast<int>(map.wrap[1]);
    const double angle = static_cast<double>(map.rotation) * (3.14159265358979323846 / 180.0);
    const float c = map.rotation == 0.0f ? 1.0f : static_cast<float>(std::cos(angle));
    const float sn = map.rotation == 0.0f ? 0.0f : static_cast<float>(std::sin(angle));
    transform[4 * s] = map.scale.x;
    transform[4 * s + 1] = map.scale.y;
    transform[4 * s + 2] = c;
    transform[4 * s + 3] = sn;
    offset[2 * s] = map.offset.x;
    offset[2 * s + 1] = map.offset.y;
    info[2 * s] = map.uv_set == 1 ? 1 : 0;
    info[2 * s + 1] = map.present() ? map.texture->level_count() : 1;
    alpha[s] = map.present() && map.texture->has_alpha ? 1 : 0;
  }
  glActiveTexture(GL_TEXTURE0);
  set_uniform_ints(program, "gloss_map_present", present, kMapSlots);
  set_uniform_ivec2s(program, "gloss_map_wrap", wrap, kMapSlots);
  set_uniform_vec4s(program, "gloss_map_transform", transform, kMapSlots);
  set_uniform_vec2s(program, "gloss_map_offset", offset, kMapSlots);
  set_uniform_ivec2s(program, "gloss_map_info", info, kMapSlots);
  set_uniform_ints(program, "gloss_map_alpha", alpha, kMapSlots);
  set_uniform(program, "gloss_map_filter", static_cast<int>(filter));
  set_uniform(program, "gloss_normal_scale", material.normal_scale);
  set_uniform(program, "gloss_bump_scale", material.bump_scale);
  set_uniform(program, "gloss_cone_spread", cone_spread);
}

}  // namespace gloss
