#pragma once
// The display shaders of shaders/, compiled into the binary at build time (src/editor/embed_glsl.cmake).

namespace gloss {

extern const char* const kDisplayVertexShader;
extern const char* const kDisplayFragmentShader;

}  // namespace gloss
