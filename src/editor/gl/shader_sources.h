#pragma once
// The display and raster shaders of shaders/, compiled into the binary at build time
// (src/editor/embed_glsl.cmake, listed in src/editor/gl/CMakeLists.txt).

namespace gloss {

extern const char* const kDisplayVertexShader;
extern const char* const kDisplayFragmentShader;
extern const char* const kRasterCommonGlsl;
extern const char* const kRasterMeshVertexShader;
extern const char* const kRasterMeshFragmentShader;
extern const char* const kRasterSphereVertexShader;
extern const char* const kRasterSphereFragmentShader;
extern const char* const kRasterSkyVertexShader;
extern const char* const kRasterSkyFragmentShader;

}  // namespace gloss
