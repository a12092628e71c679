#pragma once
// gloss without a display (no DISPLAY, or no OpenGL 3.3 window): the CPU renderer does the work
// and the results are files, so `gloss SCENE.json` on a server still produces an image.
#include <string>

#include "editor/model/script/script.h"
#include "scene/scene.h"

namespace gloss {

// Prints that there is no display (reason), renders scene at its render size to a timestamped
// PNG in the current folder (never replacing a file) and prints the path. Returns the exit
// status: 0, or 1 when the render or the write failed.
int render_without_display(const Scene& scene, const std::string& reason);

// Plays script through a command layer: `wait` returns at once (every export renders to
// convergence), viewport and term screenshots render with the CPU renderer, a window
// screenshot is an error naming the line. Returns the exit status (0, 1 failure, 2 bad line).
int run_script_without_display(const Scene& scene, const Script& script, const std::string& reason);

}  // namespace gloss
