#pragma once
// Keeps the editor's UI ahead of its background work on a machine with few cores: every thread
// of the process but the UI thread and Mesa's llvmpipe rasteriser threads (named "llvmpipe-N")
// gets a lower CPU priority (nice kBackgroundNice; Linux nice values are per thread). While the
// renderer converges on two cores, the UI thread and the GL threads that draw its frames then
// get the CPU first and the renderer the rest, instead of an even share that made UI frames wait
// (issue 13, Speed).
//
// Why a scan of /proc/self/task: the render threads are the engine's (a std::thread and oneTBB's
// workers), created where the editor has no hook, and a oneTBB observer only sees the arena of
// the thread that registers it (each external thread has its own implicit arena).
#include <set>
#include <string>

#include <sys/types.h>

namespace gloss {

constexpr int kBackgroundNice = 10;  // CFS weight 110 against 1024 for nice 0

class BackgroundPriority {
 public:
  // ui_thread: the kernel thread id kept at its priority (the caller's by default).
  BackgroundPriority();
  explicit BackgroundPriority(pid_t ui_thread);

  // Lowers the priority of threads that appeared since the last call. Cheap (one directory
  // listing); the editor calls it every frame or so. Returns how many threads it lowered.
  int update();

 private:
  pid_t m_ui;
  std::set<pid_t> m_seen;
};

// The calling thread's kernel id and nice value.
pid_t current_thread_id();
int current_thread_nice();
// The nice value of thread tid of this process; 0 when it cannot be read.
int thread_nice(pid_t tid);

}  // namespace gloss
