#pragma once
// Typed reading of a scene's JSON values. Every failure is an InputError naming the scene file
// and the field path of the offending value ("objects[2].radius", "camera.fov_y").
#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include "base/field_path.h"

namespace gloss {

// A number that is finite once converted to float (1e999 and 1e39 are refused).
float json_float(const nlohmann::json& value, const std::string& file, const std::string& field);
// An array of exactly three such numbers.
glm::vec3 json_vec3(const nlohmann::json& value, const std::string& file, const std::string& field);
// A whole number in [lo, hi]; checked before any conversion, so 1e12 cannot overflow.
long long json_integer(const nlohmann::json& value, long long lo, long long hi,
                       const std::string& file, const std::string& field);
bool json_bool(const nlohmann::json& value, const std::string& file, const std::string& field);
std::string json_string(const nlohmann::json& value, const std::string& file,
                        const std::string& field);

// One JSON object of the scene with a closed set of keys. The constructor refuses a value that
// is not an object and any key outside allowed_keys, naming the nearest allowed key.
class JsonObjectReader {
 public:
  JsonObjectReader(const nlohmann::json& value, std::string file, std::string path,
                   const std::vector<std::string>& allowed_keys);

  bool has(const std::string& key) const;
  // The value of key; a missing key is an error "missing required field".
  const nlohmann::json& required(const std::string& key) const;
  // The field path of key inside this object.
  std::string path(const std::string& key) const { return child_path(m_path, key); }
  const std::string& file() const { return m_file; }
  const std::string& path() const { return m_path; }
  [[noreturn]] void fail(const std::string& key, const std::string& message) const;

  // Required forms throw when the key is missing; the others return fallback.
  float number(const std::string& key) const;
  float number(const std::string& key, float fallback) const;
  glm::vec3 vec3(const std::string& key) const;
  glm::vec3 vec3(const std::string& key, const glm::vec3& fallback) const;
  long long integer(const std::string& key, long long fallback, long long lo, long long hi) const;
  bool boolean(const std::string& key, bool fallback) const;
  std::string string(const std::string& key) const;
  std::string string(const std::string& key, const std::string& fallback) const;

 private:
  const nlohmann::json& m_value;
  std::string m_file, m_path;
};

}  // namespace gloss
