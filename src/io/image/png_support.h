#pragma once
// What gloss's two libpng readers share (io's own, private): the error and warning callbacks,
// allocations capped at what the file can inflate to, and the opening of a file with its header
// read and the reader's transforms set. libpng reports errors by longjmp back to the setjmp in
// the run_png_* functions; those functions and the structs they touch hold no C++ object with a
// destructor, since longjmp would skip it.
#include <png.h>

#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>

namespace gloss {

struct PngError {
  char message[256] = "libpng could not allocate its state";
  char warning[128] = "";  // the last warning: libpng says why in it before a generic error
  int system_error = 0;    // errno when libpng gave up (its "Write Error" after a short fwrite)
};

// libpng's error and warning callbacks; the error pointer is a PngError.
void on_png_error(png_structp png, png_const_charp message);
void on_png_warning(png_structp png, png_const_charp message);

struct PngReadJob {
  std::FILE* file = nullptr;
  png_structp png = nullptr;
  png_infop info = nullptr;
  int width = 0, height = 0;  // after the transforms
  std::size_t row_bytes = 0;  // after the transforms
  // What the file's bytes can hold at most once inflated, 0 when its size is unknown: deflate
  // expands at most 1032:1 (zlib's documented limit: a 258-byte match coded in 2 bits).
  std::uint64_t inflated_limit = 0;
  // The image data as stored (before any transform), without filter bytes: a lower bound of
  // what the file's image data must inflate to.
  std::uint64_t stored_bytes = 0;
  std::uint64_t file_bytes = 0;
  PngError error;
};

// The transforms a reader asks of libpng once the header is known (png_set_* calls; they may
// raise libpng errors, so they run inside run_png_read_header's setjmp).
using PngTransforms = void (*)(PngReadJob& job);

// An open PNG file whose header has been read with transforms set; the libpng state is freed
// with it. Throws InputError naming path (unreadable, not a PNG, invalid header, a header that
// claims more pixels than the file can hold or than max_side allows).
class PngFile {
 public:
  PngFile(const std::string& path, int max_side, PngTransforms transforms);
  ~PngFile();
  PngFile(const PngFile&) = delete;
  PngFile& operator=(const PngFile&) = delete;

  PngReadJob& job() { return m_job; }
  // Reads every row (height pointers to row_bytes each) and the chunks after them. Throws
  // InputError.
  void read_rows(png_bytep* rows);

 private:
  void release();  // frees the libpng state (also when the constructor refuses the file)

  std::string m_path;
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> m_file;
  PngReadJob m_job;
};

}  // namespace gloss
