# Every outside library gloss uses is brought in here, and only here (included by the top-level
# CMakeLists.txt, so the imported targets are visible to every folder): Debian's packages, found
# with find_package or pkg-config (nothing is vendored, nothing is downloaded). Versions in
# comments are the Debian 12 ones the project is tested with; README.md in this folder says what
# each library does for gloss and which folder may use it.

# Ray queries (engine, reference). Debian 12: 3.13.5.
find_package(embree 3 REQUIRED)
# Parallel loops (engine, reference, analysis). Debian 12: oneTBB 2021.8.
find_package(TBB REQUIRED)
# Vectors and matrices (everywhere). Debian 12: 0.9.9.8.
find_package(glm REQUIRED)
# Scene and material JSON (io; the editor's recovery file goes through io) and the benchmark's
# JSON report (analysis), private to both. Debian 12: 3.11.2.
find_package(nlohmann_json 3 REQUIRED)
# Models: OBJ with MTL, PLY, STL, glTF 2.0 (io only, private to gloss_io). Debian 12: 5.2.5. One
# reader for every format, so triangulation (concave polygons, bridged holes), normals and
# materials behave the same whatever the file. assimp-testmodels (a package, not a build
# dependency) gives the corpus test in tests/io its files when installed.
find_package(assimp 5.2 REQUIRED)
# PNG with text chunks (io only). Debian 12: libpng 1.6.39.
find_package(PNG REQUIRED)
# OpenEXR (io only, private to gloss_io): the linear image as 32-bit float EXR beside the PFM.
# Debian 12: libopenexr-dev 3.1.5 (with Imath 3.1.6).
find_package(OpenEXR 3 REQUIRED)
# JPEG maps through libjpeg-turbo (libjpeg-dev 2.1.5; io/image/jpeg_reader.cpp says why not stb).
find_package(JPEG REQUIRED)
# Numerical integration (analysis only, private, header only): Boost.Math's adaptive
# Gauss-Kronrod quadrature with its error estimate, for the lobe view's directional albedo.
# Debian 12: libboost-dev 1.74.
find_package(Boost 1.74 REQUIRED)
# Command lines of gloss-cli and gloss. Debian 12: 2.1.2.
find_package(CLI11 REQUIRED)
# stb_easy_font.h from libstb-dev (header only, public domain): the tiny bitmap font that labels
# the panes of exported term sheets (editor/model, which is built without the editor too, so not
# through the editor's pkg-config STB). Chosen over a PSF console font because it compiles in:
# no font file to find at run time, and the package is already a dependency.
find_path(GLOSS_STB_INCLUDE_DIR stb_easy_font.h PATH_SUFFIXES stb REQUIRED)
add_library(gloss_stb_easy_font INTERFACE)
target_include_directories(gloss_stb_easy_font SYSTEM INTERFACE ${GLOSS_STB_INCLUDE_DIR})
find_package(Threads REQUIRED)
# glibc's vector maths library (libc6-dev ships it with libm): c^alpha over 16 lanes (engine).
find_library(GLOSS_LIBMVEC mvec REQUIRED)
add_library(gloss_libmvec INTERFACE)
target_link_libraries(gloss_libmvec INTERFACE ${GLOSS_LIBMVEC})

# Map images (io only): Radiance HDR through stb_image (libstb-dev's precompiled libstb, 2.27),
# OpenEXR through the OpenEXR library (libopenexr-dev 3.1.5; Blender's studio lights are
# DWAB-compressed, which smaller readers cannot decode).
find_package(PkgConfig REQUIRED)
pkg_check_modules(STB REQUIRED IMPORTED_TARGET GLOBAL stb)
find_package(OpenEXR 3 REQUIRED)

if(GLOSS_BUILD_EDITOR)
  # The window (editor/ui). Debian 12: 3.3.8.
  find_package(glfw3 3.3 REQUIRED)
  # Dear ImGui 1.86 (editor/ui). Debian's libimgui.a already holds the GLFW and OpenGL3
  # backends, and needs libstb at link time.
  pkg_check_modules(IMGUI REQUIRED IMPORTED_TARGET GLOBAL imgui)

  # The OpenGL 3.3 core loader (editor/gl), generated at build time by Debian's python3-glad
  # from its offline copy of the GL registry. --reproducible keeps it offline; naming the one
  # extension used keeps gl.c small. /usr/bin/glad, not `python3 -m glad`: python3 on PATH may
  # be an interpreter without the Debian module.
  find_program(GLAD_EXECUTABLE glad PATHS /usr/bin NO_DEFAULT_PATH REQUIRED)
  set(GLAD_OUT ${CMAKE_CURRENT_BINARY_DIR}/glad)
  add_custom_command(
    OUTPUT ${GLAD_OUT}/src/gl.c ${GLAD_OUT}/include/glad/gl.h
           ${GLAD_OUT}/include/KHR/khrplatform.h
    COMMAND ${GLAD_EXECUTABLE} --quiet --reproducible --api gl:core=3.3
            --extensions=GL_KHR_debug --out-path ${GLAD_OUT} c
    COMMENT "Generating the OpenGL 3.3 core loader with glad"
    VERBATIM)
  add_library(glad STATIC ${GLAD_OUT}/src/gl.c)
  target_include_directories(glad PUBLIC ${GLAD_OUT}/include)
endif()

if(GLOSS_BUILD_TESTS)
  # Unit tests. Debian 12: GoogleTest 1.12.1.
  find_package(GTest REQUIRED)
  if(GLOSS_BUILD_EDITOR)
    # Off-screen GL for the editor's GL tests (Mesa's surfaceless EGL platform).
    pkg_check_modules(EGL REQUIRED IMPORTED_TARGET GLOBAL egl)
  endif()
endif()
if(GLOSS_BUILD_BENCHMARKS)
  # Micro-benchmarks. Debian 12: Google Benchmark 1.7.1.
  find_package(benchmark REQUIRED)
endif()
