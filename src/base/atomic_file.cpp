#include "base/atomic_file.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include "base/error.h"

namespace gloss {

namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail_write(const std::string& path, const std::string& reason) {
  throw RuntimeFailure("cannot write " + path + ": " + reason);
}

// ".NAME.tmp-" for target FOLDER/NAME; the temporaries of one target share it.
std::string temporary_prefix(const std::string& path) {
  return "." + fs::path(path).filename().string() + ".tmp-";
}

fs::path folder_of(const std::string& path) {
  const fs::path folder = fs::path(path).parent_path();
  return folder.empty() ? fs::path(".") : folder;
}

// True when no process has the id (a process of another user still counts as alive).
bool process_is_gone(long pid) {
  return pid > 0 && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH;
}

// Removes ".NAME.tmp-PID-N" files of path's target whose PID names no live process: what a
// kill -9 of an earlier writer left behind on a file system without O_TMPFILE (or in the moment
// between linkat and rename). Failures to list or remove are ignored: this is tidying only.
void remove_stale_temporaries(const std::string& path) {
  const std::string prefix = temporary_prefix(path);
  std::error_code ec;
  for (fs::directory_iterator it(folder_of(path), ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.compare(0, prefix.size(), prefix) != 0) continue;
    char* rest = nullptr;
    const long pid = std::strtol(name.c_str() + prefix.size(), &rest, 10);
    if (rest == nullptr || *rest != '-' || !process_is_gone(pid)) continue;
    std::error_code ignored;
    fs::remove(it->path(), ignored);
  }
}

// A name beside path that no file has yet: unique per process (pid) and call (counter).
std::string next_temporary_name(const std::string& path) {
  static std::atomic<unsigned long> counter{0};
  return (folder_of(path) /
          (temporary_prefix(path) + std::to_string(static_cast<long>(::getpid())) + "-" +
           std::to_string(counter.fetch_add(1))))
      .string();
}

// An existing target keeps its permission bits across the replacement; a new file has the
// 0666 & ~umask that open applied.
void copy_target_mode(int fd, const std::string& path) {
  struct stat existing {};
  if (::stat(path.c_str(), &existing) == 0) ::fchmod(fd, existing.st_mode & 07777);
}

// Creates a new, empty named temporary beside path; O_EXCL guards against a stale file left by
// a crashed process with the same pid. Returns its name and, when fd_out is given, stores its
// open descriptor there (else closes it).
std::string create_named_temporary(const std::string& path, int* fd_out) {
  remove_stale_temporaries(path);
  for (int attempt = 0; attempt < 100; ++attempt) {
    const std::string name = next_temporary_name(path);
    const int fd = ::open(name.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) {
      copy_target_mode(fd, path);
      if (fd_out != nullptr) {
        *fd_out = fd;
      } else {
        ::close(fd);
      }
      return name;
    }
    if (errno != EEXIST) throw_write_error(path, errno);
  }
  fail_write(path, "no free temporary file name");
}

void sync_descriptor(int fd, const std::string& path) {
  if (::fsync(fd) != 0) throw_write_error(path, errno);
}

// Flushes a named temporary's data to disk so the rename never exposes an empty or partial file
// after a crash.
void sync_named(const std::string& temp_path, const std::string& path) {
  const int fd = ::open(temp_path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw_write_error(path, errno);
  try {
    sync_descriptor(fd, path);
  } catch (...) {
    ::close(fd);
    throw;
  }
  ::close(fd);
}

void rename_into_place(const std::string& temp_path, const std::string& path) {
  if (std::rename(temp_path.c_str(), path.c_str()) != 0) throw_write_error(path, errno);
}

// An unnamed file in path's folder, or -1 where the file system (or kernel) has no O_TMPFILE.
int open_unnamed_temporary(const std::string& path) {
  const int fd = ::open(folder_of(path).c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0666);
  if (fd >= 0) {
    copy_target_mode(fd, path);
    return fd;
  }
  // EISDIR or EOPNOTSUPP: no O_TMPFILE here; anything else (ENOENT, EACCES) is the folder's
  // fault and the named path reports it the same way.
  return -1;
}

// Gives the unnamed file fd a temporary name (linkat through /proc), then renames it over path.
// Returns false when /proc is not mounted, so the caller can fall back.
bool publish_unnamed(int fd, const std::string& path) {
  remove_stale_temporaries(path);  // a process killed between its linkat and its rename
  const std::string proc_link = "/proc/self/fd/" + std::to_string(fd);
  for (int attempt = 0; attempt < 100; ++attempt) {
    const std::string name = next_temporary_name(path);
    if (::linkat(AT_FDCWD, proc_link.c_str(), AT_FDCWD, name.c_str(), AT_SYMLINK_FOLLOW) == 0) {
      if (std::rename(name.c_str(), path.c_str()) != 0) {
        const int error = errno;
        ::unlink(name.c_str());
        throw_write_error(path, error);
      }
      return true;
    }
    if (errno == ENOENT && ::access("/proc/self/fd", F_OK) != 0) return false;
    if (errno != EEXIST) throw_write_error(path, errno);
  }
  fail_write(path, "no free temporary file name");
}

// Runs write on a stream over fd (which it takes over), flushes and syncs it. The stream is
// always closed; errors throw.
void write_through_stream(int fd, const std::string& path,
                          const std::function<void(std::FILE* file)>& write, bool keep_fd) {
  const int stream_fd = keep_fd ? ::dup(fd) : fd;
  if (stream_fd < 0) throw_write_error(path, errno);
  std::FILE* file = ::fdopen(stream_fd, "wb");
  if (file == nullptr) {
    const int error = errno;
    ::close(stream_fd);
    throw_write_error(path, error);
  }
  try {
    write(file);
  } catch (...) {
    std::fclose(file);
    throw;
  }
  const bool flushed = std::fflush(file) == 0 && std::ferror(file) == 0;
  const int flush_error = errno;
  if (flushed) {
    if (::fsync(::fileno(file)) != 0) {
      const int error = errno;
      std::fclose(file);
      throw_write_error(path, error);
    }
  }
  const bool closed = std::fclose(file) == 0;
  const int close_error = errno;
  if (!flushed) throw_write_error(path, flush_error != 0 ? flush_error : EIO);
  if (!closed) throw_write_error(path, close_error);
}

}  // namespace

void throw_write_error(const std::string& path, int error_number) {
  if (error_number == ENOSPC || error_number == EDQUOT) {
    throw RuntimeFailure("disk full writing " + path);
  }
  fail_write(path, std::strerror(error_number));
}

void write_stream_atomically(const std::string& path,
                             const std::function<void(std::FILE* file)>& write) {
  const int unnamed = open_unnamed_temporary(path);
  if (unnamed >= 0) {
    try {
      write_through_stream(unnamed, path, write, true);
      const bool published = publish_unnamed(unnamed, path);
      ::close(unnamed);
      if (published) return;
    } catch (...) {
      ::close(unnamed);  // the unnamed file vanishes with its last descriptor
      throw;
    }
    // No /proc: the data is written but cannot be named; write it again through a named file.
  }
  int fd = -1;
  const std::string temp_path = create_named_temporary(path, &fd);
  try {
    write_through_stream(fd, path, write, false);
    rename_into_place(temp_path, path);
  } catch (...) {
    std::remove(temp_path.c_str());
    throw;
  }
}

void write_atomically(const std::string& path,
                      const std::function<void(const std::string& temp_path)>& write) {
  const std::string temp_path = create_named_temporary(path, nullptr);
  try {
    write(temp_path);
    sync_named(temp_path, path);
    rename_into_place(temp_path, path);
  } catch (...) {
    std::remove(temp_path.c_str());
    throw;
  }
}

void write_text_atomically(const std::string& path, const std::string& text) {
  write_stream_atomically(path, [&](std::FILE* file) {
    if (std::fwrite(text.data(), 1, text.size(), file) != text.size()) {
      throw_write_error(path, errno != 0 ? errno : EIO);
    }
  });
}

std::string read_text_file(const std::string& path) {
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (file == nullptr) throw InputError(path, "cannot read: " + std::string(std::strerror(errno)));
  std::string text;
  char buffer[1 << 16];
  std::size_t count = 0;
  while ((count = std::fread(buffer, 1, sizeof buffer, file)) > 0) text.append(buffer, count);
  // A folder opens fine on Linux and fails on the first read (EISDIR).
  const bool failed = std::ferror(file) != 0;
  const int read_error = errno;
  std::fclose(file);
  if (failed) throw InputError(path, "cannot read: " + std::string(std::strerror(read_error)));
  return text;
}

}  // namespace gloss
