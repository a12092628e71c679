cmake_minimum_required(VERSION 3.20)
# The shape of src/ holds: (1) an include against the grain, or of another folder's private
# header, fails to compile with the including target's include view, while an allowed one
# compiles (so the check can fail); (2) intrinsics appear only in src/engine/simd; (3) GL only in
# src/editor/gl and src/editor/ui, GLFW and Dear ImGui only in src/editor/ui.
#   cmake -DCXX=compiler -DVIEWS=build/include-views -DSRC=repo/src -DOUT=scratch -P this
foreach(var CXX VIEWS SRC OUT)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "check_layering.cmake needs -D${var}=...")
  endif()
endforeach()
file(MAKE_DIRECTORY "${OUT}")

# TARGET|HEADER|expected (ok: compiles, refused: does not).
set(cases
  "gloss_scene|scene/scene.h|ok"
  "gloss_scene|engine/renderer.h|refused"
  "gloss_base|scene/scene.h|refused"
  "gloss_io|io/json/json_location.h|ok"
  "gloss_io|engine/renderer.h|refused"
  "gloss_shading|io/scene/scene_loader.h|refused"
  "gloss_engine|engine/trace/sample_packet.h|ok"
  "gloss_engine|io/scene/scene_loader.h|refused"
  "gloss_engine|reference/reference_renderer.h|refused"
  "gloss_engine|editor/model/document/command.h|refused"
  "gloss_reference|analysis/bench/bench.h|refused"
  "gloss_analysis|engine/trace/sample_packet.h|ok"
  "gloss-cli|analysis/bench/bench.h|ok"
  "gloss-cli|analysis/bench/paired_timing.h|refused"
  "gloss-cli|engine/renderer.h|ok"
  "gloss-cli|engine/trace/sample_packet.h|refused"
  "gloss-cli|io/json/json_location.h|refused"
  "gloss-cli|io/scene/scene_loader.h|ok"
  "gloss-cli|editor/model/document/document.h|refused"
  "gloss_editor_model|engine/progressive_renderer.h|ok"
  "gloss_editor_model|engine/simd/lane_gather.h|refused"
  "gloss_editor_model|io/json/material_json.h|refused"
  "gloss_editor_model|editor/gl/gl_texture.h|refused"
  "gloss_editor_model|editor/gl/raster/raster_renderer.h|refused"
  "gloss|editor/gl/raster/raster_renderer.h|ok")
set(failures "")
set(n 0)
foreach(case IN LISTS cases)
  string(REPLACE "|" ";" parts "${case}")
  list(GET parts 0 target)
  list(GET parts 1 header)
  list(GET parts 2 expected)
  if(NOT EXISTS "${VIEWS}/${target}")
    continue()  # a target this build does not have (no editor)
  endif()
  math(EXPR n "${n} + 1")
  set(source "${OUT}/case${n}.cpp")
  file(WRITE "${source}" "#include \"${header}\"\n")
  execute_process(COMMAND "${CXX}" -std=c++17 -fsyntax-only -I "${VIEWS}/${target}" "${source}"
                  RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET)
  if(rc EQUAL 0)
    set(got ok)
  else()
    set(got refused)
  endif()
  if(NOT got STREQUAL expected)
    string(APPEND failures "  ${target} including ${header}: ${got}, expected ${expected}\n")
  endif()
endforeach()

# Where vector intrinsics and window-system headers may appear.
file(GLOB_RECURSE sources "${SRC}/*.h" "${SRC}/*.cpp")
foreach(file IN LISTS sources)
  file(RELATIVE_PATH rel "${SRC}" "${file}")
  file(STRINGS "${file}" intrinsics REGEX "#include <[a-z]*mmintrin\\.h>|_mm[0-9]*_[a-z]|__m[0-9]+")
  if(intrinsics AND NOT rel MATCHES "^engine/simd/")
    string(APPEND failures "  ${rel}: intrinsics outside engine/simd\n")
  endif()
  file(STRINGS "${file}" gl REGEX "#include [<\"](glad/|GL/|KHR/)")
  if(gl AND NOT rel MATCHES "^editor/(gl|ui)/")
    string(APPEND failures "  ${rel}: GL outside editor/gl and editor/ui\n")
  endif()
  file(STRINGS "${file}" ui REGEX "#include [<\"](GLFW/|imgui|backends/)")
  if(ui AND NOT rel MATCHES "^editor/ui/")
    string(APPEND failures "  ${rel}: GLFW or ImGui outside editor/ui\n")
  endif()
endforeach()

if(failures)
  message(FATAL_ERROR "the shape of src/ is broken:\n${failures}")
endif()
message(STATUS "${n} include checks and the header rules hold")
