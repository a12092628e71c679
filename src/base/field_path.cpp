#include "base/field_path.h"

#include "base/error.h"

namespace gloss {

std::string child_path(const std::string& parent, const std::string& key) {
  return parent.empty() ? key : parent + "." + key;
}

std::string index_path(const std::string& parent, std::size_t index) {
  return parent + "[" + std::to_string(index) + "]";
}

void fail_field(const std::string& file, const std::string& field, const std::string& message) {
  throw InputError(file, message, 0, 0, field);
}

}  // namespace gloss
