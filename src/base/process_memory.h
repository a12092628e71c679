#pragma once
// The process's resident memory and the C allocator's share of it, and the allocator settings
// that keep freed memory from staying resident (docs/editor.md, "Memory"). glibc only: elsewhere
// the figures read 0 and the settings do nothing.
#include <cstdint>

namespace gloss {

struct ProcessMemory {
  std::uint64_t resident = 0;       // VmRSS of /proc/self/status, bytes
  std::uint64_t peak_resident = 0;  // VmHWM: the largest VmRSS so far, bytes
  std::uint64_t heap_in_use = 0;    // malloc'd and not freed (mallinfo2 uordblks + hblkhd), bytes
  std::uint64_t heap_free = 0;      // freed but kept by the allocator (fordblks), bytes; only the
                                    // pages of it that were touched are resident
};

ProcessMemory read_process_memory();

// Settings for a long-running process whose big buffers come and go (the editor): at most two
// malloc arenas instead of 8 per core (each oneTBB worker and llvmpipe thread would otherwise
// keep an arena of its own full of freed pixels), and blocks of 1 MiB or more always mapped
// on their own, so freeing one returns it to the system at once (glibc raises its mmap threshold
// to 32 MiB after the first big free, after which image-sized blocks fragment the arenas).
// Call before any thread starts.
void limit_allocator_retention();

// Hands free pages inside the allocator's arenas back to the system (malloc_trim); for an idle
// moment, it takes a few ms per 100 MB of heap. Returns the drop of resident memory, bytes.
std::uint64_t release_free_memory();

}  // namespace gloss
