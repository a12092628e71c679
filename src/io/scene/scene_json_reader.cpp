#include "io/scene/scene_json_reader.h"

#include <cmath>
#include <limits>

#include "base/error.h"
#include "base/text/text_distance.h"

namespace gloss {

namespace {

// "a number", "an array"... for "expected X, got Y" messages.
std::string describe(const nlohmann::json& value) {
  switch (value.type()) {
    case nlohmann::json::value_t::null:
      return "null";
    case nlohmann::json::value_t::boolean:
      return "a boolean";
    case nlohmann::json::value_t::string:
      return "a string";
    case nlohmann::json::value_t::array:
      return "an array";
    case nlohmann::json::value_t::object:
      return "an object";
    case nlohmann::json::value_t::number_integer:
    case nlohmann::json::value_t::number_unsigned:
    case nlohmann::json::value_t::number_float:
      return "a number";
    default:
      return value.type_name();
  }
}

[[noreturn]] void fail_type(const nlohmann::json& value, const std::string& expected,
                            const std::string& file, const std::string& field) {
  fail_field(file, field, "expected " + expected + ", got " + describe(value));
}

}  // namespace

float json_float(const nlohmann::json& value, const std::string& file, const std::string& field) {
  if (!value.is_number()) fail_type(value, "a number", file, field);
  const double number = value.get<double>();
  if (!std::isfinite(number) || std::fabs(number) > std::numeric_limits<float>::max()) {
    fail_field(file, field, "number out of range (not a finite float)");
  }
  return static_cast<float>(number);
}

glm::vec3 json_vec3(const nlohmann::json& value, const std::string& file,
                    const std::string& field) {
  if (!value.is_array()) fail_type(value, "an array of 3 numbers", file, field);
  if (value.size() != 3) {
    fail_field(file, field,
               "expected 3 numbers, got " + std::to_string(value.size()) +
                   (value.size() == 1 ? " value" : " values"));
  }
  glm::vec3 out;
  for (int i = 0; i < 3; ++i) out[i] = json_float(value[i], file, index_path(field, i));
  return out;
}

long long json_integer(const nlohmann::json& value, long long lo, long long hi,
                       const std::string& file, const std::string& field) {
  if (!value.is_number()) fail_type(value, "a whole number", file, field);
  const std::string range =
      "must be a whole number from " + std::to_string(lo) + " to " + std::to_string(hi);
  if (value.is_number_unsigned()) {
    const auto number = value.get<unsigned long long>();
    const bool below = lo > 0 && number < static_cast<unsigned long long>(lo);
    if (below || number > static_cast<unsigned long long>(hi)) {
      fail_field(file, field, range + ", got " + value.dump());
    }
    return static_cast<long long>(number);
  }
  if (value.is_number_integer()) {
    const auto number = value.get<long long>();
    if (number < lo || number > hi) fail_field(file, field, range + ", got " + value.dump());
    return number;
  }
  // A float: compared in double before any conversion so that 1e12 or 1e999 cannot overflow.
  const double number = value.get<double>();
  if (!std::isfinite(number) || number != std::floor(number) || number < static_cast<double>(lo) ||
      number > static_cast<double>(hi)) {
    fail_field(file, field, range + ", got " + value.dump());
  }
  return static_cast<long long>(number);
}

bool json_bool(const nlohmann::json& value, const std::string& file, const std::string& field) {
  if (!value.is_boolean()) fail_type(value, "true or false", file, field);
  return value.get<bool>();
}

std::string json_string(const nlohmann::json& value, const std::string& file,
                        const std::string& field) {
  if (!value.is_string()) fail_type(value, "a string", file, field);
  return value.get<std::string>();
}

JsonObjectReader::JsonObjectReader(const nlohmann::json& value, std::string file, std::string path,
                                   const std::vector<std::string>& allowed_keys)
    : m_value(value), m_file(std::move(file)), m_path(std::move(path)) {
  if (!m_value.is_object()) fail_type(m_value, "an object", m_file, m_path);
  for (const auto& item : m_value.items()) {
    bool known = false;
    for (const std::string& allowed : allowed_keys) known = known || allowed == item.key();
    if (known) continue;
    fail_field(m_file, child_path(m_path, item.key()),
               "unknown key '" + item.key() + "'" +
                   did_you_mean(nearest_words(item.key(), allowed_keys, 1)));
  }
}

bool JsonObjectReader::has(const std::string& key) const {
  return m_value.contains(key);
}

const nlohmann::json& JsonObjectReader::required(const std::string& key) const {
  const auto it = m_value.find(key);
  if (it == m_value.end()) fail(key, "missing required field");
  return *it;
}

void JsonObjectReader::fail(const std::string& key, const std::string& message) const {
  fail_field(m_file, path(key), message);
}

float JsonObjectReader::number(const std::string& key) const {
  return json_float(required(key), m_file, path(key));
}

float JsonObjectReader::number(const std::string& key, float fallback) const {
  return has(key) ? number(key) : fallback;
}

glm::vec3 JsonObjectReader::vec3(const std::string& key) const {
  return json_vec3(required(key), m_file, path(key));
}

glm::vec3 JsonObjectReader::vec3(const std::string& key, const glm::vec3& fallback) const {
  return has(key) ? vec3(key) : fallback;
}

long long JsonObjectReader::integer(const std::string& key, long long fallback, long long lo,
                                    long long hi) const {
  return has(key) ? json_integer(required(key), lo, hi, m_file, path(key)) : fallback;
}

bool JsonObjectReader::boolean(const std::string& key, bool fallback) const {
  return has(key) ? json_bool(required(key), m_file, path(key)) : fallback;
}

std::string JsonObjectReader::string(const std::string& key) const {
  return json_string(required(key), m_file, path(key));
}

std::string JsonObjectReader::string(const std::string& key, const std::string& fallback) const {
  return has(key) ? string(key) : fallback;
}

}  // namespace gloss
