// Threads of the process get the background nice value, except the UI thread and threads named
// like Mesa's llvmpipe rasterisers.
#include <gtest/gtest.h>

#include <pthread.h>

#include <atomic>
#include <thread>

#include "editor/model/session/background_priority.h"

namespace gloss {
namespace {

// A thread that waits until released, reporting its kernel id.
struct Parked {
  std::atomic<pid_t> tid{0};
  std::atomic<bool> release{false};
  std::thread thread;
  explicit Parked(const char* name) {
    thread = std::thread([this, name] {
      pthread_setname_np(pthread_self(), name);
      tid = current_thread_id();
      while (!release) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    });
    while (tid == 0) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ~Parked() {
    release = true;
    thread.join();
  }
};

TEST(BackgroundPriority, OtherThreadsAreNicedTheUiAndGlThreadsAreNot) {
  const int ui_nice = current_thread_nice();
  if (ui_nice >= kBackgroundNice) GTEST_SKIP() << "the test itself runs at nice " << ui_nice;
  Parked render("render-worker");
  Parked gl("llvmpipe-0");
  BackgroundPriority priority;
  EXPECT_GE(priority.update(), 1);
  EXPECT_EQ(thread_nice(render.tid), kBackgroundNice);
  EXPECT_EQ(thread_nice(gl.tid), ui_nice);
  EXPECT_EQ(current_thread_nice(), ui_nice);
  // A thread started later is found by the next update; known ones are not touched again.
  Parked later("later");
  EXPECT_EQ(priority.update(), 1);
  EXPECT_EQ(thread_nice(later.tid), kBackgroundNice);
}

}  // namespace
}  // namespace gloss
