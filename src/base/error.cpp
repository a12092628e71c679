#include "base/error.h"

#include "base/text/printable_text.h"

namespace gloss {

namespace {
std::string format_input_error(const std::string& file, const std::string& message, int line,
                               int column, const std::string& field) {
  std::string out = file.empty() ? std::string("<input>") : file;
  if (line > 0) {
    out += ":" + std::to_string(line);
    if (column > 0) out += ":" + std::to_string(column);
  }
  if (!field.empty()) out += ": " + field;
  return printable_text(out + ": " + message);
}
}  // namespace

InputError::InputError(std::string file, std::string message, int line, int column,
                       std::string field)
    : std::runtime_error(format_input_error(file, message, line, column, field)),
      m_file(std::move(file)),
      m_message(std::move(message)),
      m_field(std::move(field)),
      m_line(line),
      m_column(column) {}

RuntimeFailure::RuntimeFailure(const std::string& message)
    : std::runtime_error(printable_text(message)) {}

}  // namespace gloss
