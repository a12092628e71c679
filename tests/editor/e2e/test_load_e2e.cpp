// Continuous edits keep the image moving (issue 25): the real gloss under Xvfb orbits its light
// (a light edit every UI frame) beside two CPU-bound processes this test starts and stops
// itself, and the editor's own measurements (`stats`: the gaps between new images on screen and
// the edits' delays, image_cadence.h) must show a new image at least every 250 ms. Its own
// binary, run alone (RUN_SERIAL): the two busy processes are the load it is about.
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "editor/e2e/editor_process.h"

extern char** environ;

namespace gloss {
namespace {

using test::EditorRun;

// Two `sh -c 'while :; do :; done'` for the life of the object.
class BusyProcesses {
 public:
  explicit BusyProcesses(int count) {
    for (int i = 0; i < count; ++i) {
      const char* argv[] = {"sh", "-c", "while :; do :; done", nullptr};
      pid_t pid = 0;
      if (posix_spawnp(&pid, "sh", nullptr, nullptr, const_cast<char**>(argv), environ) == 0) {
        m_pids.push_back(pid);
      }
    }
  }
  ~BusyProcesses() {
    for (const pid_t pid : m_pids) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, nullptr, 0);
    }
  }
  std::size_t running() const { return m_pids.size(); }

 private:
  std::vector<pid_t> m_pids;
};

// Cores' worth of CPU time the machine spent busy (not idle or waiting on I/O) over `seconds`,
// from /proc/stat's aggregate line; -1 when it cannot be read.
double busy_cores(double seconds) {
  const auto sample = [](double& busy, double& total) {
    std::ifstream in("/proc/stat");
    std::string cpu;
    double v[8] = {};
    if (!(in >> cpu) || cpu != "cpu") return false;
    for (double& x : v) in >> x;
    total = v[0] + v[1] + v[2] + v[3] + v[4] + v[5] + v[6] + v[7];
    busy = total - v[3] - v[4];  // idle and iowait
    return static_cast<bool>(in);
  };
  double b0 = 0, t0 = 0, b1 = 0, t1 = 0;
  if (!sample(b0, t0)) return -1;
  std::this_thread::sleep_for(std::chrono::duration<double>(seconds));
  if (!sample(b1, t1) || t1 <= t0) return -1;
  const double cores = static_cast<double>(std::thread::hardware_concurrency());
  return (b1 - b0) / (t1 - t0) * cores;
}

struct Window {
  int images = 0;
  double max_gap_ms = -1, median_gap_ms = -1, median_delay_ms = -1, max_delay_ms = -1;
  int edits_shown = 0;
};

// The figures of the n-th `stats` line (0-based) of the editor's output; max_gap_ms stays -1
// when there is none.
Window stats_window(const std::string& out, int n) {
  Window w;
  std::size_t at = 0;
  for (int k = 0; k <= n; ++k) {
    at = out.find("new_images=", at);
    if (at == std::string::npos) return w;
    if (k < n) ++at;
  }
  const int read = std::sscanf(out.c_str() + at,
                               "new_images=%d image_gap_ms max=%lf median=%lf | edit_delay_ms "
                               "median=%lf max=%lf edits_shown=%d",
                               &w.images, &w.max_gap_ms, &w.median_gap_ms, &w.median_delay_ms,
                               &w.max_delay_ms, &w.edits_shown);
  if (read != 6) w.max_gap_ms = -1;
  return w;
}

class LoadE2E : public test::EditorProcessTest {
 protected:
  LoadE2E() : EditorProcessTest("gloss-load-e2e-") {}
};

constexpr double kLongestGapMs = 250;

TEST_F(LoadE2E, AnOrbitingLightKeepsTheImageMovingBesideTwoBusyProcesses) {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
  GTEST_SKIP() << "a bound on time means nothing in an instrumented build";
#endif
  // The bound is the for a quiet machine plus the two processes started here: a machine
  // already busy (other builds, another suite) is a different test, whose figures are printed
  // and not judged. Under ctest this binary runs alone (RUN_SERIAL), so CI measures it.
  const double before = busy_cores(1.0);
  BusyProcesses busy(2);
  ASSERT_EQ(busy.running(), 2u);
  // The first window settles the animation in; the second, 3 s of orbiting, is measured.
  const EditorRun r = run_editor(std::string(GLOSS_APP_TEST_DATA) + "/spheres_floor.json",
                                 "wait\nanimate on\nsleep 1\nstats\nsleep 3\nstats\n"
                                 "animate off\nquit\n",
                                 true);
  if (r.status == -1) GTEST_SKIP() << "no xvfb-run";
  ASSERT_EQ(r.status, 0) << r.err;
  const Window w = stats_window(r.out, 1);
  std::printf(
      "orbit beside two busy processes: %d new images in 3 s, gaps max %.1f ms median "
      "%.1f ms, edit delay median %.1f ms max %.1f ms\n",
      w.images, w.max_gap_ms, w.median_gap_ms, w.median_delay_ms, w.max_delay_ms);
  ASSERT_GE(w.max_gap_ms, 0.0) << r.out;
  if (before > 0.5) {
    GTEST_SKIP() << "the machine was not quiet before the test: " << before
                 << " cores busy over 1 s; the figures above are not judged";
  }
  EXPECT_LE(w.max_gap_ms, kLongestGapMs) << r.out;
  EXPECT_GE(w.images, 3000 / static_cast<int>(kLongestGapMs));
  // Each image showed a newer edit: the animation's delay is measured, not 0.
  EXPECT_GT(w.edits_shown, 0);
  EXPECT_GT(w.median_delay_ms, 0.0);
}

}  // namespace
}  // namespace gloss
