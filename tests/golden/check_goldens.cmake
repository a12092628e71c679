cmake_minimum_required(VERSION 3.20)
# Renders every case of cases.txt with gloss-cli and compares the SHA-256 of each PFM with
# checksums-SET.txt (bit-identical images). CMake's file(SHA256) does the hashing, so the check
# needs nothing beyond the build's own tools.
#   cmake -DCLI=gloss-cli -DROOT=repo -DOUT=scratch-folder -DSET=fma|sse2|sse2-scalar
#         [-DUPDATE=ON] -P check_goldens.cmake
# SET: how the renderer was compiled (tests/CMakeLists.txt chooses): with FMA (x86-64-v3: AVX2
# and AVX-512 agree bit for bit), the baseline x86-64 optimised (no FMA contraction, libmvec's
# SSE powf), or the baseline at -O1 (scalar powf). UPDATE=ON rewrites the set instead of
# comparing (scripts/update-goldens).
foreach(var CLI ROOT OUT SET)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "check_goldens.cmake needs -D${var}=...")
  endif()
endforeach()
set(golden_dir "${ROOT}/tests/golden")
file(STRINGS "${golden_dir}/cases.txt" lines)
file(REMOVE_RECURSE "${OUT}")
file(MAKE_DIRECTORY "${OUT}")

set(actual "")
foreach(line IN LISTS lines)
  if(line MATCHES "^#" OR line STREQUAL "")
    continue()
  endif()
  separate_arguments(words UNIX_COMMAND "${line}")
  list(POP_FRONT words name scene)
  set(dir "${OUT}/${name}")
  # The four terms and the total recombined from them ...
  execute_process(COMMAND "${CLI}" render "${ROOT}/${scene}" ${words} --terms "${dir}"
                  RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${name}: gloss-cli render failed (${rc}): ${err}")
  endif()
  # ... and the total alone, through the renderer's fused single-pass path.
  execute_process(COMMAND "${CLI}" render "${ROOT}/${scene}" ${words} --pfm "${dir}/alone.pfm"
                          -o "${dir}/alone.png"
                  RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${name}: gloss-cli render failed (${rc}): ${err}")
  endif()
  foreach(image emissive ambient diffuse specular total alone)
    file(SHA256 "${dir}/${image}.pfm" sum)
    string(APPEND actual "${name}/${image}.pfm ${sum}\n")
  endforeach()
endforeach()

set(checksums "${golden_dir}/checksums-${SET}.txt")
if(UPDATE)
  file(WRITE "${checksums}" "${actual}")
  message(STATUS "wrote ${checksums}")
  return()
endif()
file(READ "${checksums}" expected)
if(NOT actual STREQUAL expected)
  file(WRITE "${OUT}/actual-checksums.txt" "${actual}")
  string(REPLACE "\n" ";" expected_lines "${expected}")
  string(REPLACE "\n" ";" actual_lines "${actual}")
  set(report "")
  foreach(entry IN LISTS expected_lines)
    if(entry AND NOT entry IN_LIST actual_lines)
      string(APPEND report "  differs or missing: ${entry}\n")
    endif()
  endforeach()
  message(FATAL_ERROR "golden images changed (actual sums in ${OUT}/actual-checksums.txt):\n"
                      "${report}")
endif()
message(STATUS "all golden images bit-identical")
