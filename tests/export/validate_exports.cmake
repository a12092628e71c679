# The Khronos glTF-Validator (npm package gltf-validator, run by node) on gloss-cli export-gltf's
# files: the shipped scenes as .gltf and .glb, and spheres.json with a spot, a directional light,
# a transformed PNG diffuse map and a normal map. Fails on any validator error; without node or
# the validator it says SKIPPED, which ctest reports as a skip (scripts/common.sh installs node
# and the validator).
# cmake -DCLI=gloss-cli -DNODE=node -DROOT=source -DOUT=folder -P validate_exports.cmake
# Bad input first (no node needed): an output that is not .gltf/.glb is one error line naming
# it, exit 2, and nothing written.
file(REMOVE_RECURSE "${OUT}")
file(MAKE_DIRECTORY "${OUT}")
execute_process(COMMAND "${CLI}" export-gltf "${ROOT}/assets/scenes/spheres.json" "${OUT}/x.obj"
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 2 OR NOT err MATCHES "^error: [^\n]*x[.]obj[^\n]*\n$" OR EXISTS "${OUT}/x.obj")
  message(FATAL_ERROR "export-gltf to x.obj: exit ${status}, stderr '${err}' (want 2 and one line)")
endif()

if(NOT NODE OR NOT EXISTS "${NODE}")
  message("SKIPPED: node not found; install nodejs (scripts/start does) to validate the glTF "
          "exports")
  return()
endif()

# Where the validator may be: scripts/common.sh's folder (GLOSS_NODE_MODULES, by default
# ~/.cache/gloss/node_modules), npm's global root, Debian's and /usr/local's node folders.
if(DEFINED ENV{GLOSS_NODE_MODULES})
  set(node_path "$ENV{GLOSS_NODE_MODULES}")
else()
  set(node_path "$ENV{HOME}/.cache/gloss/node_modules")
endif()
find_program(NPM npm)
if(NPM)
  execute_process(COMMAND ${NPM} root -g OUTPUT_VARIABLE npm_root OUTPUT_STRIP_TRAILING_WHITESPACE
                  ERROR_QUIET)
  set(node_path "${node_path}:${npm_root}")
endif()
set(node_path "${node_path}:/usr/lib/node_modules:/usr/local/lib/node_modules")

# Without the package the test is skipped, saying why (ctest's SKIP_REGULAR_EXPRESSION: a
# `cmake -P` script cannot choose its exit status before CMake 3.29, so SKIP_RETURN_CODE is not
# open to it); with node and the package, any validator error fails it.
execute_process(COMMAND ${CMAKE_COMMAND} -E env "NODE_PATH=${node_path}"
                        "${NODE}" -e "require.resolve('gltf-validator')"
                RESULT_VARIABLE status OUTPUT_QUIET ERROR_QUIET)
if(NOT status EQUAL 0)
  message("SKIPPED: node cannot find the npm package gltf-validator (looked in ${node_path}); "
          "scripts/common.sh's gloss_install_gltf_validator fetches it")
  return()
endif()

# spheres.json with more lights, a scaled, turned and moved diffuse map (KHR_texture_transform)
# and a normal map.
file(READ "${ROOT}/assets/scenes/spheres.json" scene)
string(JSON scene SET "${scene}" lights 1
  "{\"type\": \"spot\", \"position\": [0, 4, 1], \"direction\": [0, -1, 0], \"cutoff\": 30, \"inner\": 20}")
string(JSON scene SET "${scene}" lights 2
  "{\"type\": \"directional\", \"direction\": [1, -1, -1], \"diffuse\": [0.3, 0.3, 0.3]}")
string(JSON scene SET "${scene}" materials floor diffuse_map
  "{\"file\": \"${ROOT}/assets/icon/gloss.png\", \"scale\": [2, 3], \"rotation\": 30, \"offset\": [0.25, -0.5]}")
string(JSON scene SET "${scene}" materials floor normal_map "\"${ROOT}/assets/icon/gloss.png\"")
file(WRITE "${OUT}/textured.json" "${scene}")

set(scenes "${ROOT}/assets/scenes/spheres.json" "${ROOT}/assets/scenes/cornell-teapot.json"
           "${ROOT}/assets/scenes/studio-metals.json" "${OUT}/textured.json")
foreach(path IN LISTS scenes)
  get_filename_component(stem "${path}" NAME_WE)
  foreach(ext gltf glb)
    set(file "${OUT}/${stem}.${ext}")
    execute_process(COMMAND "${CLI}" export-gltf "${path}" "${file}"
                    RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(NOT status EQUAL 0)
      message(FATAL_ERROR "gloss-cli export-gltf ${path} ${file}: exit ${status}\n${out}${err}")
    endif()
    execute_process(COMMAND ${CMAKE_COMMAND} -E env "NODE_PATH=${node_path}"
                            "${NODE}" "${ROOT}/tests/export/validate_gltf.js" "${file}"
                    RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
    message("${out}${err}")
    if(NOT status EQUAL 0)
      message(FATAL_ERROR "glTF-Validator reports errors for ${file} (exit ${status})")
    endif()
  endforeach()
endforeach()
