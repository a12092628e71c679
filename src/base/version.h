#pragma once
// The version gloss-cli --version and gloss --version print and PNGs carry in their "Software"
// chunk: the project() version of the top-level CMakeLists.txt.
namespace gloss {

const char* gloss_version();

}  // namespace gloss
