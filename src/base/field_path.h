#pragma once
// Names of the fields of a document, as errors print them: "objects[2].radius", "camera.fov_y".
#include <cstddef>
#include <string>

namespace gloss {

// "parent.key", or "key" at the top level.
std::string child_path(const std::string& parent, const std::string& key);
// "parent[index]".
std::string index_path(const std::string& parent, std::size_t index);

// Throws InputError(file, message, 0, 0, field).
[[noreturn]] void fail_field(const std::string& file, const std::string& field,
                             const std::string& message);

}  // namespace gloss
