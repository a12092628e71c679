#pragma once
// Running the real gloss binary in a per-test folder, under Xvfb or without a display, for the
// end-to-end tests. Paths come from compile definitions (GLOSS_EDITOR_PATH, GLOSS_XVFB_RUN).
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace gloss::test {

struct EditorRun {
  // gloss's exit status; -1 when a display was asked for and there is no xvfb-run; 1000 + the
  // wrapper's status when gloss never started.
  int status = -1;
  std::string out, err;
};

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A fixture with a fresh folder per test (config and state directories inside it, so the
// user's own settings and recovery file are never touched).
class EditorProcessTest : public ::testing::Test {
 protected:
  explicit EditorProcessTest(std::string prefix) : m_prefix(std::move(prefix)) {}

  void SetUp() override {
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    m_dir = std::filesystem::temp_directory_path() / (m_prefix + info->name());
    std::filesystem::remove_all(m_dir);
    std::filesystem::create_directories(m_dir);
  }

  // Runs gloss on scene with script_text as its --script; with_display = false runs it without X.
  // options: more of gloss's options ("--window-width 1024 --window-height 640").
  // gloss runs from run.sh, which writes gloss's own exit status to status.txt: xvfb-run's
  // status is not gloss's when its clean-up fails (it exits 5 when it cannot remove its
  // temporary folder, seen once in CI after gloss had exited 2 as expected).
  EditorRun run_editor(const std::string& scene, const std::string& script_text, bool with_display,
                       const std::string& options = "") {
    if (with_display && std::string(GLOSS_XVFB_RUN).empty()) return {};
    for (const char* name : {"status.txt", "out.txt", "err.txt", "wrapper-err.txt"}) {
      std::filesystem::remove(m_dir / name);  // a second run's files are its own
    }
    std::ofstream(m_dir / "script.txt") << script_text;
    std::ofstream(m_dir / "run.sh")
        << "'" << GLOSS_EDITOR_PATH << "' '" << scene << "' --script script.txt " << options
        << " > out.txt 2> err.txt\n"
        << "echo $? > status.txt\n";
    std::string command = "cd '" + m_dir.string() + "' && XDG_CONFIG_HOME='" + m_dir.string() +
                          "/config' XDG_STATE_HOME='" + m_dir.string() + "/state' ";
    if (with_display) {
      command += std::string(GLOSS_XVFB_RUN) + " -a -s '-screen 0 1280x800x24' ";
    } else {
      command += "env -u DISPLAY -u WAYLAND_DISPLAY ";
    }
    command += "sh run.sh 2> wrapper-err.txt";
    const int raw = std::system(command.c_str());
    EditorRun r;
    r.out = read_text(m_dir / "out.txt");
    r.err = read_text(m_dir / "err.txt");
    const std::string status = read_text(m_dir / "status.txt");
    if (!status.empty()) {
      r.status = std::stoi(status);  // 128 + signal when gloss was killed (sh's convention)
    } else {
      // gloss never ran (Xvfb did not start, say): a failure, with the wrapper's words.
      r.status = WIFEXITED(raw) ? 1000 + WEXITSTATUS(raw) : 1000;
      r.err += read_text(m_dir / "wrapper-err.txt");
    }
    return r;
  }

  std::filesystem::path m_dir;

 private:
  std::string m_prefix;
};

}  // namespace gloss::test
