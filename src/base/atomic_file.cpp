#include "base/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "base/error.h"

namespace gloss {

namespace {

std::string errno_text(int error_number) {
  return std::strerror(error_number);
}

[[noreturn]] void fail_write(const std::string& path, const std::string& reason) {
  throw RuntimeFailure("cannot write " + path + ": " + reason);
}

// Creates a new, empty temporary file beside path (same folder, so the final rename stays within
// one file system) and returns its name. The name is unique per process (pid) and per call
// (counter); O_EXCL guards against a stale file left by a crashed process with the same pid.
std::string create_temporary_beside(const std::string& path) {
  static std::atomic<unsigned long> counter{0};
  const std::filesystem::path target(path);
  const std::string prefix = "." + target.filename().string() + ".tmp-" +
                             std::to_string(static_cast<long>(::getpid())) + "-";
  for (int attempt = 0; attempt < 100; ++attempt) {
    const std::string name =
        (target.parent_path() / (prefix + std::to_string(counter.fetch_add(1)))).string();
    const int fd = ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) {
      // An existing target keeps its permission bits across the replacement.
      struct stat existing {};
      if (::stat(path.c_str(), &existing) == 0) ::fchmod(fd, existing.st_mode & 07777);
      ::close(fd);
      return name;
    }
    if (errno != EEXIST) fail_write(path, errno_text(errno));
  }
  fail_write(path, "no free temporary file name");
}

// Flushes the temporary's data to disk so the rename never exposes an empty or partial file
// after a crash.
void sync_file(const std::string& temp_path, const std::string& path) {
  const int fd = ::open(temp_path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) fail_write(path, errno_text(errno));
  const bool synced = ::fsync(fd) == 0;
  const int sync_error = errno;
  ::close(fd);
  if (!synced) fail_write(path, errno_text(sync_error));
}

}  // namespace

void write_atomically(const std::string& path,
                      const std::function<void(const std::string& temp_path)>& write) {
  const std::string temp_path = create_temporary_beside(path);
  try {
    write(temp_path);
    sync_file(temp_path, path);
    if (std::rename(temp_path.c_str(), path.c_str()) != 0) fail_write(path, errno_text(errno));
  } catch (...) {
    std::remove(temp_path.c_str());
    throw;
  }
}

void write_text_atomically(const std::string& path, const std::string& text) {
  write_atomically(path, [&](const std::string& temp_path) {
    std::FILE* file = std::fopen(temp_path.c_str(), "wb");
    if (file == nullptr) fail_write(path, errno_text(errno));
    const bool written = std::fwrite(text.data(), 1, text.size(), file) == text.size();
    const int write_error = errno;
    const bool closed = std::fclose(file) == 0;
    if (!written) fail_write(path, errno_text(write_error));
    if (!closed) fail_write(path, errno_text(errno));
  });
}

std::string read_text_file(const std::string& path) {
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (file == nullptr) throw InputError(path, "cannot read: " + errno_text(errno));
  std::string text;
  char buffer[1 << 16];
  std::size_t count = 0;
  while ((count = std::fread(buffer, 1, sizeof buffer, file)) > 0) text.append(buffer, count);
  // A folder opens fine on Linux and fails on the first read (EISDIR).
  const bool failed = std::ferror(file) != 0;
  const int read_error = errno;
  std::fclose(file);
  if (failed) throw InputError(path, "cannot read: " + errno_text(read_error));
  return text;
}

}  // namespace gloss
