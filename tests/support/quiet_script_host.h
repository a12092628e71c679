#pragma once
// A ScriptHost for model tests: owns the document's command layer and view settings, remembers
// the selection, and lets every host action (wait, screenshot, stats, sleep, quality) pass.
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "editor/model/document/command_layer.h"
#include "editor/model/script/script.h"
#include "editor/model/script/script_runner.h"
#include "editor/model/view/view_settings.h"

namespace gloss::test {

class QuietScriptHost : public ScriptHost {
 public:
  explicit QuietScriptHost(Scene scene) : m_layer(std::move(scene)) {}
  CommandLayer& layer() override { return m_layer; }
  ViewSettings& view() override { return m_view; }
  void select(int object) override { m_selected = object; }
  void select_objects(const std::vector<int>& objects) override {
    m_selected = objects.empty() ? m_selected : objects.front();
    m_selected_all = objects;
  }
  const std::vector<int>& selected_all() const { return m_selected_all; }
  int selected_object() const override { return m_selected; }
  LineResult wait(const WaitAction&, const std::string&) override { return LineResult::go_on(); }
  LineResult screenshot(const ScreenshotAction&, const std::string&) override {
    return LineResult::go_on();
  }
  LineResult stats() override { return LineResult::go_on(); }
  LineResult sleep(const SleepAction&) override { return LineResult::go_on(); }
  LineResult quality(const QualityAction&, const std::string&) override {
    return LineResult::go_on();
  }

 private:
  CommandLayer m_layer;
  ViewSettings m_view;
  int m_selected = 0;
  std::vector<int> m_selected_all;
};

// Runs the lines of text on host until one stops, their output captured (not shown); the last
// line's result.
inline LineResult run_quietly(const std::string& text, QuietScriptHost& host) {
  const Script s = parse_script(text, "run.txt");
  LineResult r;
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  for (const ScriptLine& line : s.lines) {
    r = run_script_line(s, line, host);
    if (r.next == LineResult::Next::stop) break;
  }
  testing::internal::GetCapturedStderr();
  testing::internal::GetCapturedStdout();
  return r;
}

}  // namespace gloss::test
