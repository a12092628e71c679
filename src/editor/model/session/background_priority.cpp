#include "editor/model/session/background_priority.h"

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace gloss {

namespace {

// The thread's name as the kernel keeps it (pthread_setname_np; "llvmpipe-0" for Mesa's).
std::string thread_name(pid_t tid) {
  std::ifstream in("/proc/self/task/" + std::to_string(tid) + "/comm");
  std::string name;
  std::getline(in, name);
  return name;
}

}  // namespace

pid_t current_thread_id() {
  return static_cast<pid_t>(syscall(SYS_gettid));
}

int thread_nice(pid_t tid) {
  errno = 0;
  const int nice = getpriority(PRIO_PROCESS, static_cast<id_t>(tid));
  return errno == 0 ? nice : 0;
}

int current_thread_nice() {
  return thread_nice(current_thread_id());
}

BackgroundPriority::BackgroundPriority() : BackgroundPriority(current_thread_id()) {}

BackgroundPriority::BackgroundPriority(pid_t ui_thread) : m_ui(ui_thread) {}

int BackgroundPriority::update() {
  int lowered = 0;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator("/proc/self/task", ec)) {
    const pid_t tid = static_cast<pid_t>(std::atoi(entry.path().filename().c_str()));
    if (tid <= 0 || tid == m_ui || !m_seen.insert(tid).second) continue;
    if (thread_name(tid).rfind("llvmpipe", 0) == 0) continue;  // draws the UI's frames
    // Raising a nice value needs no privilege; a failure leaves the thread as it was.
    if (thread_nice(tid) < kBackgroundNice &&
        setpriority(PRIO_PROCESS, static_cast<id_t>(tid), kBackgroundNice) == 0) {
      ++lowered;
    }
  }
  return lowered;
}

}  // namespace gloss
