#pragma once
// Writes that never leave a partial file and whose temporaries cannot outlive their process.
// In-process writers write to an unnamed file (O_TMPFILE) in the target's folder that gets a
// name only once it is complete and synced (linkat, then rename over the target: rename is
// atomic within one file system), so a kill -9 while writing leaves nothing behind. Where the
// file system has no O_TMPFILE, and for outside programs that need a path, the temporary is
// named ".NAME.tmp-PID-N" beside the target; such files whose process is gone are removed by the
// next atomic write of the same target.
#include <cstdio>
#include <functional>
#include <string>

namespace gloss {

// Calls write(file) on a stream opened for binary writing, then makes its contents path's. The
// stream is closed here; write may throw, and then nothing is left behind. Throws RuntimeFailure
// "cannot write PATH: REASON", or "disk full writing PATH" when the disk or quota is full.
void write_stream_atomically(const std::string& path,
                             const std::function<void(std::FILE* file)>& write);

// Writes text atomically (write_stream_atomically).
void write_text_atomically(const std::string& path, const std::string& text);

// For writers that need a path (an outside program): calls write(temp_path) with a named
// temporary beside path and renames it to path; on any exception removes the temporary and
// rethrows. Throws RuntimeFailure when the folder cannot be written.
void write_atomically(const std::string& path,
                      const std::function<void(const std::string& temp_path)>& write);

// Throws the RuntimeFailure for errno error_number while writing path: "disk full writing PATH"
// for ENOSPC and EDQUOT, else "cannot write PATH: strerror".
[[noreturn]] void throw_write_error(const std::string& path, int error_number);

// Reads a whole file; throws InputError("cannot read ...") naming path.
std::string read_text_file(const std::string& path);

}  // namespace gloss
