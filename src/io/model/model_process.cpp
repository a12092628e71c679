#include "io/model/model_process.h"

#include <poll.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>
#include <stdexcept>
#include <type_traits>

#include "base/error.h"
#include "base/memory_budget.h"

// Present only in sanitizer builds (weak: null elsewhere).
extern "C" void __sanitizer_set_death_callback(void (*)(void)) __attribute__((weak));

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define GLOSS_SANITIZED_BUILD 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define GLOSS_SANITIZED_BUILD 1
#endif
#endif

namespace gloss {

namespace {

// The pipe's format: one tag byte ('M' a Model follows, 'E' an InputError follows), then
// little-endian sizes and raw arrays. Both ends are this program, so no versioning. Each record
// is one field list (the *_fields templates below) that both ends run: the Writer appends the
// fields, the Reader fills them in the same order, so the two cannot disagree on the layout.
struct Writer {
  std::string bytes;
  template <class T>
  void raw(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    bytes.append(reinterpret_cast<const char*>(&value), sizeof value);
  }
  // A field by its type: a string as its size and bytes, a vector as its size and elements
  // (trivially copyable), anything else as its bytes.
  void field(const std::string& s) {
    raw<std::uint64_t>(s.size());
    bytes += s;
  }
  template <class T>
  void field(const std::vector<T>& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    raw<std::uint64_t>(v.size());
    if (!v.empty()) bytes.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
  }
  template <class T>
  void field(const T& value) {
    raw(value);
  }
  template <class... T>
  void operator()(const T&... fields) {
    (field(fields), ...);
  }
  // A count, then each element through each(element).
  template <class T, class Each>
  void list(const std::vector<T>& v, Each each) {
    raw<std::uint64_t>(v.size());
    for (const T& element : v) each(element);
  }
};

// Throws std::length_error where the bytes end early.
struct Reader {
  const std::string& bytes;
  std::size_t at = 0;
  void need(std::size_t n) {
    if (n > bytes.size() - at) throw std::length_error("truncated");
  }
  // The next field, of type T.
  template <class T>
  T next() {
    T value;
    field(value);
    return value;
  }
  void field(std::string& s) {
    const auto n = next<std::uint64_t>();
    need(n);
    s = bytes.substr(at, n);
    at += n;
  }
  template <class T>
  void field(std::vector<T>& v) {
    const auto n = next<std::uint64_t>();
    if (n > (bytes.size() - at) / sizeof(T)) throw std::length_error("truncated");
    v.resize(n);
    if (n > 0) std::memcpy(v.data(), bytes.data() + at, n * sizeof(T));  // data() may be null
    at += n * sizeof(T);
  }
  template <class T>
  void field(T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    need(sizeof value);
    std::memcpy(&value, bytes.data() + at, sizeof value);
    at += sizeof value;
  }
  template <class... T>
  void operator()(T&... fields) {
    (field(fields), ...);
  }
  // A count, then that many elements, each filled by each(element) and appended to v.
  template <class T, class Each>
  void list(std::vector<T>& v, Each each) {
    const auto n = next<std::uint64_t>();
    for (std::uint64_t i = 0; i < n; ++i) {
      T element;
      each(element);
      v.push_back(std::move(element));
    }
  }
};

// The records' fields. Io: Writer (with const records) or Reader.
template <class Io, class M>
void material_fields(Io& io, M& m) {
  io(m.ambient, m.diffuse, m.specular, m.emission, m.shininess, m.preset);
}

template <class Io, class T>
void texture_ref_fields(Io& io, T& t) {
  io(t.type, t.path, t.uv_set, t.wrap_u, t.wrap_v, t.transformed, t.translation, t.scaling,
     t.rotation, t.strength);
}

// The residuals and `fitted` are not sent: the parent computes them (fit_metal_rough_materials).
template <class Io, class M>
void file_material_fields(Io& io, M& m) {
  io.list(m.textures, [&io](auto& t) { texture_ref_fields(io, t); });
  io(m.gltf, m.base_colour, m.metallic, m.roughness, m.alpha_mode, m.alpha_cutoff, m.gloss_exact);
}

template <class Io, class P>
void part_fields(Io& io, P& part) {
  io(part.material_name, part.mesh.positions, part.mesh.normals, part.mesh.triangles,
     part.mesh.uv[0], part.mesh.uv[1], part.mesh.tangents);
}

template <class Io, class I>
void embedded_image_fields(Io& io, I& image) {
  io(image.name, image.bytes);
}

std::string pack(const Model& model) {
  Writer w;
  w.raw('M');
  w.list(model.parts, [&w](const ModelPart& part) { part_fields(w, part); });
  w.raw<std::uint64_t>(model.materials.size());
  for (std::size_t i = 0; i < model.materials.size(); ++i) {
    w(model.material_names[i]);
    material_fields(w, model.materials[i]);
    file_material_fields(
        w, i < model.file_materials.size() ? model.file_materials[i] : ModelFileMaterial{});
  }
  w.list(model.embedded,
         [&w](const ModelEmbeddedImage& image) { embedded_image_fields(w, image); });
  w.list(model.warnings, [&w](const std::string& warning) { w(warning); });
  return w.bytes;
}

Model unpack(Reader& r) {
  Model model;
  r.list(model.parts, [&r](ModelPart& part) { part_fields(r, part); });
  const auto materials = r.next<std::uint64_t>();
  for (std::uint64_t i = 0; i < materials; ++i) {
    model.material_names.push_back(r.next<std::string>());
    material_fields(r, model.materials.emplace_back());
    file_material_fields(r, model.file_materials.emplace_back());
  }
  r.list(model.embedded, [&r](ModelEmbeddedImage& image) { embedded_image_fields(r, image); });
  r.list(model.warnings, [&r](std::string& warning) { r(warning); });
  return model;
}

// An InputError's place and message, after the tag 'E'.
struct ErrorRecord {
  std::string file, message;
  std::int32_t line = 0, column = 0;
  std::string field;
};

template <class Io, class E>
void error_fields(Io& io, E& e) {
  io(e.file, e.message, e.line, e.column, e.field);
}

std::string pack_error(const InputError& e) {
  Writer w;
  w.raw('E');
  const ErrorRecord record{e.file(), e.message(), e.line(), e.column(), e.field()};
  error_fields(w, record);
  return w.bytes;
}

bool write_all(int fd, const std::string& bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

// The child: import, send, and leave with _exit (no atexit handlers or destructors of the
// parent's state run twice; a leak inside the library dies with the process).
[[noreturn]] void run_child(int fd, const std::string& path,
                            const std::function<Model(const std::string&)>& import) {
  // The child dies plainly: no handler of the parent (a crash reporter, libFuzzer's unit writer,
  // a sanitizer's death callback) runs for the library's fault; the parent reports it.
  for (int sig : {SIGSEGV, SIGBUS, SIGILL, SIGFPE, SIGABRT}) std::signal(sig, SIG_DFL);
  if (__sanitizer_set_death_callback != nullptr) __sanitizer_set_death_callback(nullptr);
#ifndef GLOSS_SANITIZED_BUILD
  // What a file merely declares (a few KB asking for GBs) fails as bad_alloc once the child has
  // grown by the memory budget (sanitizer runtimes reserve terabytes of address space, so not
  // under them).
  unsigned long long pages = 0;
  if (std::FILE* statm = std::fopen("/proc/self/statm", "r")) {
    if (std::fscanf(statm, "%llu", &pages) != 1) pages = 0;
    std::fclose(statm);
  }
  const rlim_t limit_bytes =
      static_cast<rlim_t>(pages) * static_cast<rlim_t>(sysconf(_SC_PAGESIZE)) +
      memory_budget_bytes();
  const rlimit limit{limit_bytes, limit_bytes};
  setrlimit(RLIMIT_AS, &limit);
#endif
  int status = 0;
  try {
    status = write_all(fd, pack(import(path))) ? 0 : 3;
  } catch (const InputError& e) {
    status = write_all(fd, pack_error(e)) ? 0 : 3;
  } catch (const std::bad_alloc&) {
    status = 4;
  } catch (...) {
    status = 5;
  }
  ::close(fd);
  ::_exit(status);
}

std::string describe(int status) {
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    const char* name = strsignal(sig);
    return std::string("crashed with signal ") + std::to_string(sig) + " (" +
           (name != nullptr ? name : "?") + ")";
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == 4) return "ran out of memory";
  if (WIFEXITED(status)) return "stopped with status " + std::to_string(WEXITSTATUS(status));
  return "stopped";
}

}  // namespace

int import_time_limit_seconds() {
  const char* text = std::getenv(kImportTimeVariable);
  if (text != nullptr) {
    char* end = nullptr;
    const long value = std::strtol(text, &end, 10);
    if (end != text && *end == '\0' && value >= 1 && value <= 86400) return static_cast<int>(value);
  }
  return kDefaultImportTimeSeconds;
}

Model import_in_child_process(const std::string& path,
                              const std::function<Model(const std::string&)>& import) {
  int fds[2];
  if (::pipe(fds) != 0)
    throw RuntimeFailure("cannot create a pipe: " + std::string(strerror(errno)));
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw RuntimeFailure("cannot start the model import: " + std::string(strerror(errno)));
  }
  if (pid == 0) {
    ::close(fds[0]);
    run_child(fds[1], path, import);
  }
  ::close(fds[1]);
  // Read everything before waiting: a big model fills the pipe, and the child only exits once
  // it has been read.
  std::string bytes;
  char buffer[65536];
  const int limit_s = import_time_limit_seconds();
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(limit_s);
  bool timed_out = false;
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    pollfd wait_for{fds[0], POLLIN, 0};
    const int ready = ::poll(&wait_for, 1, static_cast<int>(std::max<long long>(0, left.count())));
    if (ready < 0 && errno == EINTR) continue;
    if (ready == 0) {
      timed_out = true;
      break;
    }
    const ssize_t n = ::read(fds[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    bytes.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(fds[0]);
  if (timed_out) ::kill(pid, SIGKILL);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (timed_out) {
    throw InputError(path, "the model library did not finish reading this file in " +
                               std::to_string(limit_s) + " s (" + kImportTimeVariable +
                               " sets the limit)");
  }
  const bool clean = WIFEXITED(status) && WEXITSTATUS(status) == 0 && !bytes.empty();
  if (!clean)
    throw InputError(path, "the model library failed on this file (" + describe(status) + ")");
  Reader r{bytes};
  try {
    const char tag = r.next<char>();
    if (tag == 'M') return unpack(r);
    ErrorRecord e;
    error_fields(r, e);
    throw InputError(e.file, e.message, e.line, e.column, e.field);
  } catch (const std::length_error&) {
    throw InputError(path, "the model library failed on this file (incomplete result)");
  }
}

}  // namespace gloss
