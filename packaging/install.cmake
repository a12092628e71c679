# Installation and the Debian package (cmake --install, cpack -G DEB). The layout is the one
# base/assets.cpp looks for beside the executable, so any prefix works:
#   PREFIX/bin/gloss, PREFIX/bin/gloss-cli
#   PREFIX/share/gloss/assets/          presets table, teapot patches, scenes
#   PREFIX/share/doc/gloss/             the guides (--help and the Help window point here)
#   PREFIX/share/applications/gloss.desktop
#   PREFIX/share/icons/hicolor/256x256/apps/gloss.png
# share/ is fixed (not CMAKE_INSTALL_DATADIR): the programs find it as ../share from bin/.
set(GLOSS_SHARE share)

install(TARGETS gloss-cli RUNTIME DESTINATION bin)
# A GLOSS_ISA_VARIANTS build (docs/engine.md, "One build for every x86-64"): libgloss_core.so
# in PREFIX/lib/gloss/ (the baseline level) and PREFIX/lib/gloss/glibc-hwcaps/LEVEL/ (each higher
# level, where glibc's loader looks first when the CPU runs it); the programs find it through
# their RUNPATH, relative to bin/.
if(GLOSS_ISA_VARIANTS)
  list(GET GLOSS_ISA_LEVELS 0 baseline)
  foreach(level ${GLOSS_ISA_LEVELS})
    set(dest lib/gloss/glibc-hwcaps/${level})
    if(level STREQUAL baseline)
      set(dest lib/gloss)
    endif()
    install(TARGETS gloss_core.${level} LIBRARY DESTINATION ${dest})
  endforeach()
  set_target_properties(gloss-cli PROPERTIES INSTALL_RPATH "$ORIGIN/../lib/gloss")
  if(GLOSS_BUILD_EDITOR AND GLOSS_BUILD_EDITOR_APP)
    set_target_properties(gloss PROPERTIES INSTALL_RPATH "$ORIGIN/../lib/gloss")
  endif()
endif()
if(GLOSS_BUILD_EDITOR AND GLOSS_BUILD_EDITOR_APP)
  install(TARGETS gloss RUNTIME DESTINATION bin)
  install(FILES ${PROJECT_SOURCE_DIR}/packaging/gloss.desktop
          DESTINATION ${GLOSS_SHARE}/applications)
  install(FILES ${PROJECT_SOURCE_DIR}/assets/icon/gloss.png
          DESTINATION ${GLOSS_SHARE}/icons/hicolor/256x256/apps)
endif()
# The icon's scene stays in the source tree (assets/icon/README.md); the programs do not need it.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/assets/ DESTINATION ${GLOSS_SHARE}/gloss/assets
        PATTERN icon EXCLUDE)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${GLOSS_SHARE}/doc/gloss)
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${GLOSS_SHARE}/doc/gloss)

# cpack -G DEB in the build folder. dpkg-shlibdeps works out Depends from the installed
# programs' shared libraries (libglfw3, libembree3, libtbb12, libassimp5, libpng16, ...).
set(CPACK_PACKAGE_NAME gloss)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Live Phong material editor and CPU ray tracer")
set(CPACK_PACKAGE_CONTACT "gloss maintainers <gloss@localhost>")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# The editor draws with OpenGL 3.3 through Mesa when no vendor driver is installed.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "libgl1-mesa-dri")
set(CPACK_GENERATOR DEB)
include(CPack)
