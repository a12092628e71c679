#pragma once
// Typed errors. Parsing and I/O throw these; only the CLI's main and the editor's error dialog turn
// them into messages and exit codes (docs/spec/scene-and-cli.md: 2 = bad input, 1 = other failure).
#include <stdexcept>
#include <string>

namespace gloss {

// Bad input: unreadable, malformed or invalid scene/material/mesh file, impossible setting.
// what() is one line: "FILE:LINE:COL: MESSAGE" when a position is known, "FILE: FIELD: MESSAGE"
// when a field is known, else "FILE: MESSAGE". It passes through printable_text
// (base/text/printable_text.h), so control characters and broken UTF-8 from the input (a name with ESC
// or \r in it) reach no terminal raw; file(), message() and field() keep the bytes as given.
class InputError : public std::runtime_error {
 public:
  InputError(std::string file, std::string message, int line = 0, int column = 0,
             std::string field = {});
  const std::string& file() const { return m_file; }
  const std::string& message() const { return m_message; }
  const std::string& field() const { return m_field; }
  int line() const { return m_line; }
  int column() const { return m_column; }

 private:
  std::string m_file, m_message, m_field;
  int m_line, m_column;
};

// A failure that is not the input's fault (cannot write an output, out of memory, Embree error).
// what() is message through printable_text, as for InputError.
class RuntimeFailure : public std::runtime_error {
 public:
  explicit RuntimeFailure(const std::string& message);
};

}  // namespace gloss
