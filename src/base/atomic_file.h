#pragma once
// Writes that never leave a partial file: data goes to a temporary name beside the target, is
// flushed, then renamed over it (rename is atomic within one file system).
#include <functional>
#include <string>

namespace gloss {

// Calls write(temp_path) and renames temp_path to path; on any exception removes the temporary
// and rethrows. Throws RuntimeFailure when the folder cannot be written.
void write_atomically(const std::string& path,
                      const std::function<void(const std::string& temp_path)>& write);

// Writes text atomically.
void write_text_atomically(const std::string& path, const std::string& text);

// Reads a whole file; throws InputError("cannot read ...") naming path.
std::string read_text_file(const std::string& path);

}  // namespace gloss
