#include "io/image/png_support.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include "base/error.h"

namespace gloss {

void on_png_error(png_structp png, png_const_charp message) {
  auto* error = static_cast<PngError*>(png_get_error_ptr(png));
  error->system_error = errno;
  // "Invalid IHDR data" follows the warning that names the field ("Image width exceeds user
  // limit in IHDR"): both, so the user learns which.
  if (error->warning[0] != '\0') {
    std::snprintf(error->message, sizeof error->message, "%s (%s)", message, error->warning);
  } else {
    std::snprintf(error->message, sizeof error->message, "%s", message);
  }
  png_longjmp(png, 1);
}

// Warnings (an unknown chunk, a benign CRC policy note) do not stop reading or writing; the last
// one is kept for the error that may follow.
void on_png_warning(png_structp png, png_const_charp message) {
  auto* error = static_cast<PngError*>(png_get_error_ptr(png));
  if (error != nullptr) std::snprintf(error->warning, sizeof error->warning, "%s", message);
}

namespace {

// libpng allocates a chunk (text, ICC profile) at its declared length before reading it, even
// past its chunk_malloc_max, which only warns for ancillary chunks: a 900-byte file declaring a
// 1.9 GB tEXt got 1.9 GB. No allocation larger than the file can inflate to is granted; libpng
// skips an ancillary chunk it cannot allocate and fails on a critical one.
png_voidp allocate_for_png_read(png_structp png, png_alloc_size_t size) {
  const auto* job = static_cast<const PngReadJob*>(png_get_mem_ptr(png));
  if (job != nullptr && job->inflated_limit > 0 && size > job->inflated_limit) return nullptr;
  return std::malloc(size);
}

void free_for_png(png_structp, png_voidp pointer) {
  std::free(pointer);
}

// Reads the header (the 8 signature bytes are already consumed), then sets the reader's
// transforms and updates the info to them.
bool run_png_read_header(PngReadJob& job, int max_side, PngTransforms transforms) {
  job.png = png_create_read_struct_2(PNG_LIBPNG_VER_STRING, &job.error, on_png_error,
                                     on_png_warning, &job, allocate_for_png_read, free_for_png);
  if (job.png == nullptr) return false;
  job.info = png_create_info_struct(job.png);
  if (job.info == nullptr) return false;
  if (setjmp(png_jmpbuf(job.png))) return false;
  png_init_io(job.png, job.file);
  png_set_sig_bytes(job.png, 8);
  // libpng refuses a larger header before anything is allocated for it (its own default allows
  // 1e6 x 1e6).
  png_set_user_limits(job.png, static_cast<png_uint_32>(max_side),
                      static_cast<png_uint_32>(max_side));
  png_read_info(job.png, job.info);
  const std::uint64_t stored_bits =
      static_cast<std::uint64_t>(png_get_image_width(job.png, job.info)) *
      png_get_image_height(job.png, job.info) * png_get_channels(job.png, job.info) *
      png_get_bit_depth(job.png, job.info);
  job.stored_bytes = stored_bits / 8;
  transforms(job);
  png_set_interlace_handling(job.png);
  png_read_update_info(job.png, job.info);
  job.width = static_cast<int>(png_get_image_width(job.png, job.info));
  job.height = static_cast<int>(png_get_image_height(job.png, job.info));
  job.row_bytes = png_get_rowbytes(job.png, job.info);
  return true;
}

// Reads the pixels and the chunks after them (text may follow the image data).
bool run_png_read_pixels(PngReadJob& job, png_bytep* rows) {
  if (setjmp(png_jmpbuf(job.png))) return false;
  png_read_image(job.png, rows);
  png_read_end(job.png, job.info);
  return true;
}

}  // namespace

PngFile::PngFile(const std::string& path, int max_side, PngTransforms transforms)
    : m_path(path), m_file(std::fopen(path.c_str(), "rb"), &std::fclose) {
  if (!m_file) throw InputError(path, std::string("cannot read: ") + std::strerror(errno));
  png_byte signature[8] = {};
  if (std::fread(signature, 1, sizeof signature, m_file.get()) != sizeof signature ||
      png_sig_cmp(signature, 0, sizeof signature) != 0) {
    throw InputError(path, "not a PNG file");
  }
  m_job.file = m_file.get();
  std::error_code size_error;
  const std::uint64_t file_bytes = std::filesystem::file_size(path, size_error);
  if (!size_error) {
    m_job.file_bytes = file_bytes;
    m_job.inflated_limit = 1032 * file_bytes;
  }
  // A constructor that throws runs no destructor: the libpng state made so far is freed here.
  const auto refuse = [&](const std::string& why) {
    release();
    throw InputError(path, why);
  };
  if (!run_png_read_header(m_job, max_side, transforms)) {
    refuse(std::string("invalid PNG: ") + m_job.error.message);
  }
  // A header claiming more pixels than the file can inflate to is refused before the pixel
  // buffer is allocated: 57 bytes cannot hold a 16384 x 16384 image.
  if (m_job.inflated_limit > 0 && m_job.stored_bytes > m_job.inflated_limit) {
    refuse("invalid PNG: its header claims " + std::to_string(m_job.width) + "x" +
           std::to_string(m_job.height) + " pixels, more than its " + std::to_string(file_bytes) +
           " bytes can hold");
  }
}

PngFile::~PngFile() {
  release();
}

void PngFile::release() {
  if (m_job.png != nullptr) png_destroy_read_struct(&m_job.png, &m_job.info, nullptr);
  m_job.png = nullptr;
  m_job.info = nullptr;
}

void PngFile::read_rows(png_bytep* rows) {
  if (!run_png_read_pixels(m_job, rows)) {
    throw InputError(m_path, std::string("invalid PNG: ") + m_job.error.message);
  }
}

}  // namespace gloss
