#include "io/json/field_json.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "base/text_distance.h"

namespace gloss {

std::string float_text(float f) {
  char text[40] = {};
  for (int digits = 6; digits <= 9; ++digits) {
    std::snprintf(text, sizeof text, "%.*g", digits, static_cast<double>(f));
    if (static_cast<float>(std::strtod(text, nullptr)) == f) break;
  }
  return text;
}

nlohmann::json float_json(float f) {
  const std::string text = float_text(f);
  const double d = std::strtod(text.c_str(), nullptr);
  if (d == std::floor(d) && std::fabs(d) < 1e15) return static_cast<long long>(d);
  return d;
}

FieldValue read_field_value(const JsonObjectReader& reader, const std::string& key,
                            const std::string& label, FieldKind kind, double min, double max,
                            const std::vector<const char*>& choices) {
  FieldValue value;
  switch (kind) {
    case FieldKind::colour:
      value.v = reader.vec3(key) + glm::vec3(0.0f);  // + 0 turns -0 into +0
      break;
    case FieldKind::vector:
      value.v = reader.vec3(key);
      break;
    case FieldKind::number:
      value.x = reader.number(key);
      break;
    case FieldKind::whole:
      value.x = static_cast<double>(
          reader.integer(key, 0, static_cast<long long>(min), static_cast<long long>(max)));
      break;
    case FieldKind::flag:
      value.x = reader.boolean(key, false) ? 1.0 : 0.0;
      break;
    case FieldKind::choice: {
      const std::string name = reader.string(key);
      std::vector<std::string> names(choices.begin(), choices.end());
      for (std::size_t i = 0; i < names.size(); ++i) {
        if (names[i] == name) {
          value.x = static_cast<double>(i);
          return value;
        }
      }
      reader.fail(key, "unknown " + label + " '" + name + "'" +
                           did_you_mean(nearest_words(name, names, 1)));
    }
  }
  return value;
}

nlohmann::json field_value_json(FieldKind kind, const std::vector<const char*>& choices,
                                const FieldValue& value) {
  switch (kind) {
    case FieldKind::colour:
    case FieldKind::vector:
      return nlohmann::json::array(
          {float_json(value.v.x), float_json(value.v.y), float_json(value.v.z)});
    case FieldKind::number:
      return float_json(static_cast<float>(value.x));
    case FieldKind::whole:
      return static_cast<long long>(value.x);
    case FieldKind::flag:
      return value.x != 0.0;
    case FieldKind::choice:
      return choices.at(static_cast<std::size_t>(value.x));
  }
  return nullptr;
}

}  // namespace gloss
