#pragma once
// Compiling and linking one GL program from a vertex and a fragment shader's text: the one place
// the editor's programs (display, raster) and the GL tests' hosts are built.
#include <string>

#include <glad/gl.h>

namespace gloss {

// One compiled shader of stage (GL_VERTEX_SHADER, GL_FRAGMENT_SHADER); throws
// std::runtime_error naming what and carrying the compiler's log.
GLuint compile_shader(GLenum stage, const std::string& text, const std::string& what);

// The linked program; throws std::runtime_error naming what (e.g. "the display shaders") and
// carrying the compiler's or linker's log. Nothing is left allocated when it throws.
GLuint build_program(const std::string& vertex_text, const std::string& fragment_text,
                     const std::string& what);

}  // namespace gloss
