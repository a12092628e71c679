#pragma once
// Runs a model import in a child process. Debian's assimp 5.2.5 is not memory-safe on hostile
// files: fuzzing (fuzz/, issue 11) found it reading past a buffer in its glTF binary reader,
// crashing on malformed MTL and glTF input, leaking on error paths and allocating what a file
// merely declares (687 MB from a few KB). We cannot fix the system library, so no byte of a
// model file reaches assimp in the process that holds the user's document: the child imports,
// sends the Model back through a pipe and exits; if it dies instead, the file is refused as bad
// input and the editor keeps its scene.
#include <functional>
#include <string>

#include "io/model/model_loader.h"

namespace gloss {

// A hostile file can also keep the library busy for ever (fuzzing found a 100-byte PLY header
// that does): the child gets GLOSS_IMPORT_TIME_LIMIT_S seconds (default 120; a million-triangle
// OBJ imports in a few seconds here), then is killed and the file refused.
inline const char* const kImportTimeVariable = "GLOSS_IMPORT_TIME_LIMIT_S";
constexpr int kDefaultImportTimeSeconds = 120;
int import_time_limit_seconds();

// Calls import(path) in a forked child and returns its Model. An InputError thrown in the child
// is rethrown here as it was; a child that crashes, is killed, or exits without a model becomes
// InputError(path, "the model library failed on this file (...)"); one that runs past the time
// limit is killed and refused the same way.
Model import_in_child_process(const std::string& path,
                              const std::function<Model(const std::string&)>& import);

}  // namespace gloss
