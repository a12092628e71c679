# Writes OUT, a C++ file defining kPhongContractGlsl from CONTRACT (shaders/phong_contract.glsl).
# Run at build time so an edited contract rebuilds the exporter.
file(READ ${CONTRACT} GLOSS_CONTRACT)
file(WRITE ${OUT}.tmp
  "// Generated from shaders/phong_contract.glsl by embed_contract.cmake; edit that file instead.\n"
  "#include \"editor/model/glsl_export.h\"\n"
  "namespace gloss {\n"
  "const char* const kPhongContractGlsl = R\"glsl(${GLOSS_CONTRACT})glsl\";\n"
  "}  // namespace gloss\n")
file(COPY_FILE ${OUT}.tmp ${OUT} ONLY_IF_DIFFERENT)
file(REMOVE ${OUT}.tmp)
