# Writes OUT, a C++ file defining the display shaders' sources as string constants, from the
# files in SHADER_DIR. Run at build time so an edited shader rebuilds the editor.
file(READ ${SHADER_DIR}/display.vert GLOSS_VERT)
file(READ ${SHADER_DIR}/display.frag GLOSS_FRAG)
file(WRITE ${OUT}.tmp
  "// Generated from shaders/ by embed_shaders.cmake; edit the .vert/.frag files instead.\n"
  "#include \"editor/gl/shader_sources.h\"\n"
  "namespace gloss {\n"
  "const char* const kDisplayVertexShader = R\"glsl(${GLOSS_VERT})glsl\";\n"
  "const char* const kDisplayFragmentShader = R\"glsl(${GLOSS_FRAG})glsl\";\n"
  "}  // namespace gloss\n")
file(COPY_FILE ${OUT}.tmp ${OUT} ONLY_IF_DIFFERENT)
file(REMOVE ${OUT}.tmp)
