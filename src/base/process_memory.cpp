#include "base/process_memory.h"

#include <cstdio>
#include <cstring>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace gloss {

namespace {

constexpr int kArenas = 2;
// Below the engine's per-plane arrays (4 B x the pixels of a 640 x 480 pane is 1.2 MB) and above
// everything small that is allocated per frame or per edit.
constexpr int kMmapThresholdBytes = 1 << 20;

// The value in kB of a "Name:   123 kB" line of /proc/self/status, in bytes; 0 when absent.
std::uint64_t status_bytes(const char* text, const char* name) {
  const char* line = std::strstr(text, name);
  if (line == nullptr) return 0;
  unsigned long long kb = 0;
  if (std::sscanf(line + std::strlen(name), " %llu", &kb) != 1) return 0;
  return static_cast<std::uint64_t>(kb) * 1024;
}

}  // namespace

ProcessMemory read_process_memory() {
  ProcessMemory m;
  if (std::FILE* f = std::fopen("/proc/self/status", "r")) {
    char text[8192];
    const std::size_t n = std::fread(text, 1, sizeof(text) - 1, f);
    text[n] = '\0';
    std::fclose(f);
    m.resident = status_bytes(text, "\nVmRSS:");
    m.peak_resident = status_bytes(text, "\nVmHWM:");
  }
#if defined(__GLIBC__) && (__GLIBC__ > 2 || __GLIBC_MINOR__ >= 33)
  const struct mallinfo2 info = mallinfo2();
  m.heap_in_use = info.uordblks + info.hblkhd;
  m.heap_free = info.fordblks;
#endif
  return m;
}

void limit_allocator_retention() {
#if defined(__GLIBC__)
  mallopt(M_ARENA_MAX, kArenas);
  mallopt(M_MMAP_THRESHOLD, kMmapThresholdBytes);  // a fixed threshold stops the raising
#endif
}

std::uint64_t release_free_memory() {
  const std::uint64_t before = read_process_memory().resident;
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
  const std::uint64_t after = read_process_memory().resident;
  return before > after ? before - after : 0;
}

}  // namespace gloss
