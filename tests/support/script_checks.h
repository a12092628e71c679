#pragma once
// What the script tests share: a bad line's error, and running a whole script on a quiet host.
#include <string>

#include <gtest/gtest.h>

#include "base/error.h"
#include "editor/model/script/script.h"
#include "editor/model/script/script_runner.h"

namespace gloss::test {

// Parsing text (as "bad.txt") fails at line with "bad.txt:LINE: " and words in the message.
inline void expect_script_error(const std::string& text, int line, const std::string& words) {
  try {
    parse_script(text, "bad.txt");
    ADD_FAILURE() << "no error for: " << text;
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_EQ(e.file(), "bad.txt");
    EXPECT_NE(std::string(e.what()).find("bad.txt:" + std::to_string(line) + ":"),
              std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

// Runs every line of text (as file) on host; returns the status of the line that stopped the
// script, 0 when none did; errors: what it printed on stderr (stdout is swallowed).
inline int run_script_text(const std::string& text, const std::string& file, ScriptHost& host,
                           std::string& errors) {
  const Script s = parse_script(text, file);
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  int status = 0;
  for (const ScriptLine& line : s.lines) {
    const LineResult r = run_script_line(s, line, host);
    if (r.next == LineResult::Next::stop) {
      status = r.status;
      break;
    }
  }
  errors = testing::internal::GetCapturedStderr();
  testing::internal::GetCapturedStdout();
  return status;
}

}  // namespace gloss::test
