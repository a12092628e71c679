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
// little-endian sizes and raw arrays. Both ends are this program, so no versioning.
struct Writer {
  std::string bytes;
  template <class T>
  void raw(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    bytes.append(reinterpret_cast<const char*>(&value), sizeof value);
  }
  void text(const std::string& s) {
    raw<std::uint64_t>(s.size());
    bytes += s;
  }
  template <class T>
  void array(const std::vector<T>& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    raw<std::uint64_t>(v.size());
    if (!v.empty()) bytes.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
  }
};

struct Reader {
  const std::string& bytes;
  std::size_t at = 0;
  void need(std::size_t n) {
    if (n > bytes.size() - at) throw std::length_error("truncated");
  }
  template <class T>
  T raw() {
    need(sizeof(T));
    T value;
    std::memcpy(&value, bytes.data() + at, sizeof value);
    at += sizeof value;
    return value;
  }
  std::string text() {
    const auto n = raw<std::uint64_t>();
    need(n);
    std::string s = bytes.substr(at, n);
    at += n;
    return s;
  }
  template <class T>
  std::vector<T> array() {
    const auto n = raw<std::uint64_t>();
    if (n > (bytes.size() - at) / sizeof(T)) throw std::length_error("truncated");
    std::vector<T> v(n);
    if (n > 0) std::memcpy(v.data(), bytes.data() + at, n * sizeof(T));  // data() may be null
    at += n * sizeof(T);
    return v;
  }
};

void write_material(Writer& w, const Material& m) {
  w.raw(m.ambient);
  w.raw(m.diffuse);
  w.raw(m.specular);
  w.raw(m.emission);
  w.raw(m.shininess);
  w.text(m.preset);
}

Material read_material(Reader& r) {
  Material m;
  m.ambient = r.raw<glm::vec3>();
  m.diffuse = r.raw<glm::vec3>();
  m.specular = r.raw<glm::vec3>();
  m.emission = r.raw<glm::vec3>();
  m.shininess = r.raw<float>();
  m.preset = r.text();
  return m;
}

void write_file_material(Writer& w, const ModelFileMaterial& m) {
  w.raw<std::uint64_t>(m.textures.size());
  for (const ModelTextureRef& t : m.textures) {
    w.raw(t.type);
    w.text(t.path);
    w.raw(t.uv_set);
    w.raw(t.wrap_u);
    w.raw(t.wrap_v);
    w.raw(t.transformed);
    w.raw(t.translation);
    w.raw(t.scaling);
    w.raw(t.rotation);
    w.raw(t.strength);
  }
  w.raw(m.gltf);
  w.raw(m.base_colour);
  w.raw(m.metallic);
  w.raw(m.roughness);
  w.text(m.alpha_mode);
  w.raw(m.alpha_cutoff);
  w.raw(m.gloss_exact);
}

ModelFileMaterial read_file_material(Reader& r) {
  ModelFileMaterial m;
  const auto count = r.raw<std::uint64_t>();
  for (std::uint64_t i = 0; i < count; ++i) {
    ModelTextureRef t;
    t.type = r.raw<int>();
    t.path = r.text();
    t.uv_set = r.raw<int>();
    t.wrap_u = r.raw<int>();
    t.wrap_v = r.raw<int>();
    t.transformed = r.raw<bool>();
    const auto translation = r.raw<std::array<float, 2>>();
    const auto scaling = r.raw<std::array<float, 2>>();
    t.translation[0] = translation[0];
    t.translation[1] = translation[1];
    t.scaling[0] = scaling[0];
    t.scaling[1] = scaling[1];
    t.rotation = r.raw<float>();
    t.strength = r.raw<float>();
    m.textures.push_back(std::move(t));
  }
  m.gltf = r.raw<bool>();
  m.base_colour = r.raw<glm::vec4>();
  m.metallic = r.raw<float>();
  m.roughness = r.raw<float>();
  m.alpha_mode = r.text();
  m.alpha_cutoff = r.raw<float>();
  m.gloss_exact = r.raw<bool>();
  return m;
}

std::string pack(const Model& model) {
  Writer w;
  w.raw('M');
  w.raw<std::uint64_t>(model.parts.size());
  for (const ModelPart& part : model.parts) {
    w.text(part.material_name);
    w.array(part.mesh.positions);
    w.array(part.mesh.normals);
    w.array(part.mesh.triangles);
    w.array(part.mesh.uv[0]);
    w.array(part.mesh.uv[1]);
    w.array(part.mesh.tangents);
  }
  w.raw<std::uint64_t>(model.materials.size());
  for (std::size_t i = 0; i < model.materials.size(); ++i) {
    w.text(model.material_names[i]);
    write_material(w, model.materials[i]);
    write_file_material(
        w, i < model.file_materials.size() ? model.file_materials[i] : ModelFileMaterial{});
  }
  w.raw<std::uint64_t>(model.embedded.size());
  for (const ModelEmbeddedImage& image : model.embedded) {
    w.text(image.name);
    w.text(image.bytes);
  }
  w.raw<std::uint64_t>(model.warnings.size());
  for (const std::string& warning : model.warnings) w.text(warning);
  return w.bytes;
}

Model unpack(Reader& r) {
  Model model;
  const auto parts = r.raw<std::uint64_t>();
  for (std::uint64_t i = 0; i < parts; ++i) {
    ModelPart part;
    part.material_name = r.text();
    part.mesh.positions = r.array<glm::vec3>();
    part.mesh.normals = r.array<glm::vec3>();
    part.mesh.triangles = r.array<glm::uvec3>();
    part.mesh.uv[0] = r.array<glm::vec2>();
    part.mesh.uv[1] = r.array<glm::vec2>();
    part.mesh.tangents = r.array<glm::vec4>();
    model.parts.push_back(std::move(part));
  }
  const auto materials = r.raw<std::uint64_t>();
  for (std::uint64_t i = 0; i < materials; ++i) {
    model.material_names.push_back(r.text());
    model.materials.push_back(read_material(r));
    model.file_materials.push_back(read_file_material(r));
  }
  const auto images = r.raw<std::uint64_t>();
  for (std::uint64_t i = 0; i < images; ++i) {
    ModelEmbeddedImage image;
    image.name = r.text();
    image.bytes = r.text();
    model.embedded.push_back(std::move(image));
  }
  const auto warnings = r.raw<std::uint64_t>();
  for (std::uint64_t i = 0; i < warnings; ++i) model.warnings.push_back(r.text());
  return model;
}

std::string pack_error(const InputError& e) {
  Writer w;
  w.raw('E');
  w.text(e.file());
  w.text(e.message());
  w.raw<std::int32_t>(e.line());
  w.raw<std::int32_t>(e.column());
  w.text(e.field());
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
    const char tag = r.raw<char>();
    if (tag == 'M') return unpack(r);
    const std::string file = r.text(), message = r.text();
    const int line = r.raw<std::int32_t>(), column = r.raw<std::int32_t>();
    throw InputError(file, message, line, column, r.text());
  } catch (const std::length_error&) {
    throw InputError(path, "the model library failed on this file (incomplete result)");
  }
}

}  // namespace gloss
