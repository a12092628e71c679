# The installed layout (packaging/install.cmake), checked as a user gets it: cmake --install into a
# fresh prefix, the prefix moved elsewhere (any prefix works), then the installed programs run from
# there with GLOSS_ASSETS unset.
# Arguments: -DBUILD=build folder -DOUT=scratch folder -DEDITOR=ON|OFF [-DVALIDATE=desktop-file-validate]
#            [-DISA_LEVELS=x86-64-v2;x86-64-v3;... for a GLOSS_ISA_VARIANTS build]
cmake_minimum_required(VERSION 3.20)
file(REMOVE_RECURSE ${OUT})
set(first ${OUT}/first-prefix)
set(prefix ${OUT}/moved/prefix)

execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD} --prefix ${first}
                RESULT_VARIABLE status OUTPUT_VARIABLE log ERROR_VARIABLE log)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${status}):\n${log}")
endif()
file(MAKE_DIRECTORY ${OUT}/moved)
file(RENAME ${first} ${prefix})

set(expected bin/gloss-cli share/gloss/assets/scenes/spheres.json
             share/gloss/assets/materials/opengl-vrml.csv share/gloss/assets/models/utah-teapot.txt
             share/doc/gloss/editor.md share/doc/gloss/spec/scene-and-cli.md)
# A GLOSS_ISA_VARIANTS build (ISA_LEVELS: its levels, baseline first): one libgloss_core.so per
# level, the higher ones where glibc's loader looks for them.
foreach(level IN LISTS ISA_LEVELS)
  if(level STREQUAL "${ISA_LEVELS}" OR ISA_LEVELS MATCHES "^${level};")
    list(APPEND expected lib/gloss/libgloss_core.so)
  else()
    list(APPEND expected lib/gloss/glibc-hwcaps/${level}/libgloss_core.so)
  endif()
endforeach()
if(EDITOR)
  list(APPEND expected bin/gloss share/applications/gloss.desktop
                       share/icons/hicolor/256x256/apps/gloss.png)
endif()
foreach(file ${expected})
  if(NOT EXISTS ${prefix}/${file})
    message(FATAL_ERROR "not installed: ${file}")
  endif()
endforeach()
if(EXISTS ${prefix}/share/gloss/assets/icon)
  message(FATAL_ERROR "the icon's source folder was installed with the assets")
endif()

# The installed gloss-cli must read the installed assets, not the source tree's: a preset row added
# to the installed table only shows if it does.
file(APPEND ${prefix}/share/gloss/assets/materials/opengl-vrml.csv
     "installedmarker,0.1,0.1,0.1,0.5,0.5,0.5,0.2,0.2,0.2,0.25\n")
execute_process(COMMAND ${CMAKE_COMMAND} -E env --unset=GLOSS_ASSETS ${prefix}/bin/gloss-cli presets
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0 OR NOT out MATCHES "installedmarker")
  message(FATAL_ERROR "installed gloss-cli presets (${status}) did not read the installed table:\n${out}${err}")
endif()

# A shipped scene renders from the installed tree (its presets and, for the teapot, the patches).
foreach(scene spheres teapot)
  execute_process(
    COMMAND ${CMAKE_COMMAND} -E env --unset=GLOSS_ASSETS ${prefix}/bin/gloss-cli render
            ${prefix}/share/gloss/assets/scenes/${scene}.json -o ${OUT}/${scene}.png
            --width 64 --height 48
    RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0 OR NOT EXISTS ${OUT}/${scene}.png)
    message(FATAL_ERROR "installed gloss-cli render ${scene}.json failed (${status}):\n${out}${err}")
  endif()
endforeach()

if(EDITOR)
  # --help needs no display; it names the installed guide.
  execute_process(COMMAND ${prefix}/bin/gloss --help
                  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  string(FIND "${out}" "${prefix}/share/doc/gloss/editor.md" at)
  if(NOT status EQUAL 0 OR at LESS 0)
    message(FATAL_ERROR "gloss --help (${status}) does not name ${prefix}/share/doc/gloss/editor.md:\n${out}${err}")
  endif()
  file(STRINGS ${prefix}/share/applications/gloss.desktop desktop)
  if(NOT "Exec=gloss %f" IN_LIST desktop OR NOT "Icon=gloss" IN_LIST desktop)
    message(FATAL_ERROR "gloss.desktop lacks Exec=gloss %f or Icon=gloss")
  endif()
  if(VALIDATE)
    execute_process(COMMAND ${VALIDATE} ${prefix}/share/applications/gloss.desktop
                    RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(NOT status EQUAL 0 OR NOT "${out}${err}" STREQUAL "")
      message(FATAL_ERROR "desktop-file-validate (${status}):\n${out}${err}")
    endif()
  endif()
endif()
message(STATUS "installed layout under ${prefix}: ok")
