#pragma once
// What loading a scene said, as every subcommand that loads one prints it on stderr: a `note:`
// line per note (how a model's glTF materials were read, each as the fitted Phong or by assimp's
// rule with both errors, as the editor's Add model lists them), then a `warning:` line per
// warning. Neither changes the exit status.
#include <string>
#include <vector>

namespace gloss {

void print_scene_messages(const std::vector<std::string>& notes,
                          const std::vector<std::string>& warnings);

}  // namespace gloss
