#pragma once
// The raster path's GL programs (raster_renderer.h), built on first use from the shaders/ files:
// a version line and #defines for the variant, shaders/raster_common.glsl, the shading contract
// shaders/phong_contract.glsl, then the stage's own file. One program per variant, kept.
#include <functional>
#include <map>
#include <string>
#include <tuple>
#include <utility>

#include <glad/gl.h>

namespace gloss {

// sky: the environment where primary rays miss, one triangle over the image.
enum class RasterShape { mesh, sphere, sky };
// shadow: distances to a light for its shadow maps; pixel / vertex: the five term outputs with
// the contract per pixel or per mesh vertex (spheres are per pixel in both).
enum class RasterPass { shadow, pixel, vertex };

struct RasterVariant {
  RasterShape shape = RasterShape::mesh;
  RasterPass pass = RasterPass::pixel;
  int light_count = 0;       // GLOSS_LIGHT_COUNT
  bool shadows = false;      // GLOSS_SHADOWS: the shading passes look up the shadow maps
  bool environment = false;  // GLOSS_ENVIRONMENT: the environment's fast path (environment.glsl)
  bool maps = false;         // GLOSS_MAPS: the material has maps (shaders/texture_lookup.glsl)
  // Bit t set: the program handles lights of LightType t (GLOSS_POINT_LIGHTS,
  // GLOSS_DIRECTIONAL_LIGHTS, GLOSS_SPOT_LIGHTS), and shadow maps of LightShadow::Kind k
  // (GLOSS_SHADOW_CUBE_MAPS, ..._PERSPECTIVE_MAPS, ..._ORTHOGRAPHIC_MAPS): those it looks up
  // in a shading pass, the kind of view it draws in a shadow pass. The code for the others is
  // left out: llvmpipe pays for both sides of a branch on a uniform. All by default.
  int light_types = 7;
  int shadow_kinds = 7;
  int model = 0;                  // GLOSS_MODEL: 0 Phong, 1 Blinn-Phong (phong_contract.glsl)
  bool energy_normalize = false;  // GLOSS_ENERGY_NORMALIZE
  bool operator<(const RasterVariant& o) const {
    return std::tie(shape, pass, light_count, shadows, environment, maps, light_types, shadow_kinds,
                    model, energy_normalize) <
           std::tie(o.shape, o.pass, o.light_count, o.shadows, o.environment, o.maps, o.light_types,
                    o.shadow_kinds, o.model, o.energy_normalize);
  }
};

// The most lights a raster program takes: its uniform arrays (7 vectors per light for the
// contract, 5 more for its shadow map's frame and layers: at most 48 components each as vec4
// slots) and its shadow-map layers (at most 6 per light) stay within GL 3.3's guaranteed
// minimums (1024 fragment uniform components, 256 array layers). A scene with more lights gets
// the ray tracer, with a notice.
inline constexpr int kMaxRasterLights = 16;

class RasterPrograms {
 public:
  // edit, when set, rewrites each stage's text before it is compiled (raster_renderer.h).
  explicit RasterPrograms(std::function<std::string(const std::string&)> edit = {})
      : m_edit(std::move(edit)) {}
  ~RasterPrograms();
  RasterPrograms(const RasterPrograms&) = delete;
  RasterPrograms& operator=(const RasterPrograms&) = delete;

  // The program of variant, built now if it is new; throws std::runtime_error with the GL log
  // (and the variant) when it does not compile or link.
  GLuint get(const RasterVariant& variant);

  // The GLSL text of one stage of variant (tests print it when a build fails).
  static std::string source(const RasterVariant& variant, GLenum stage);

 private:
  std::function<std::string(const std::string&)> m_edit;
  std::map<RasterVariant, GLuint> m_programs;
};

// Uniform setters by name on the program in use (glGetUniformLocation each time: a hash lookup,
// a few dozen per frame). Unknown or optimised-away names are ignored, as GL does with -1.
void set_uniform(GLuint program, const char* name, int value);
void set_uniform(GLuint program, const char* name, float value);
void set_uniform(GLuint program, const char* name, float x, float y);
void set_uniform(GLuint program, const char* name, const float* xyz, int count = 1);
// Arrays of vec2, vec4 and ivec2 (count entries).
void set_uniform_vec2s(GLuint program, const char* name, const float* xy, int count);
void set_uniform_vec4s(GLuint program, const char* name, const float* xyzw, int count);
void set_uniform_ivec2s(GLuint program, const char* name, const int* xy, int count);
void set_uniform_ints(GLuint program, const char* name, const int* x, int count);
void set_uniform_ivec4s(GLuint program, const char* name, const int* xyzw, int count);

}  // namespace gloss
