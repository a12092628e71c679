#include "scene/fields/field.h"

#include <cmath>
#include <cstdio>
#include <limits>

namespace gloss {

namespace {

// Bounds and values as people write them: whole numbers without a fraction ("16384",
// "1000000"), others with %g.
std::string number_text(double x) {
  char text[40];
  if (std::isfinite(x) && x == std::floor(x) && std::fabs(x) < 1e15) {
    std::snprintf(text, sizeof text, "%.0f", x);
  } else {
    std::snprintf(text, sizeof text, "%g", x);
  }
  return text;
}

// "must be from 0 to 1000000", "must be >= 0", "must be between 0 and 180 (exclusive)".
std::string range_text(double min, double max, bool open_min, bool open_max) {
  const bool has_min = std::isfinite(min), has_max = std::isfinite(max);
  if (has_min && has_max) {
    if (open_min && open_max) {
      return "must be between " + number_text(min) + " and " + number_text(max) + " (exclusive)";
    }
    return "must be from " + number_text(min) + (open_min ? " (exclusive)" : "") + " to " +
           number_text(max) + (open_max ? " (exclusive)" : "");
  }
  if (has_min) return std::string("must be ") + (open_min ? "> " : ">= ") + number_text(min);
  if (has_max) return std::string("must be ") + (open_max ? "< " : "<= ") + number_text(max);
  return "must be a finite number";
}

bool in_range(double x, double min, double max, bool open_min, bool open_max) {
  return (open_min ? x > min : x >= min) && (open_max ? x < max : x <= max);
}

// A map's settings: a texture coordinate set of 0 or 1, finite scale, rotation and offset within
// the coordinate range the lookups keep exact (docs/spec/shading.md: coordinates up to 1e6).
FieldProblem map_problem(const TextureMap& map) {
  if (map.uv_set != 0 && map.uv_set != 1) return {"uv_set must be 0 or 1"};
  const double values[] = {map.scale.x, map.scale.y, map.offset.x, map.offset.y, map.rotation};
  const char* names[] = {"scale", "scale", "offset", "offset", "rotation"};
  for (int k = 0; k < 5; ++k) {
    if (!std::isfinite(values[k]) || std::fabs(values[k]) > 1e6) {
      return {std::string(names[k]) + " must be a finite number from -1000000 to 1000000, got " +
              number_text(values[k])};
    }
  }
  if (map.present() && !map.named()) return {"a map must name its file"};
  return {};
}

}  // namespace

FieldProblem field_problem(FieldKind kind, double min, double max, bool open_min, bool open_max,
                           const std::vector<const char*>& choices, const FieldValue& value) {
  switch (kind) {
    case FieldKind::colour:
    case FieldKind::vector:
      for (int c = 0; c < 3; ++c) {
        const double x = value.v[c];
        if (!std::isfinite(x)) return {"must be a finite number", c};
        if (!in_range(x, min, max, open_min, open_max)) {
          return {range_text(min, max, open_min, open_max) + ", got " + number_text(x), c};
        }
      }
      return {};
    case FieldKind::number:
      // Number fields are floats: finite means finite once converted (1e39 is not).
      if (!std::isfinite(value.x) || std::fabs(value.x) > std::numeric_limits<float>::max()) {
        return {"must be a finite number, got " + number_text(value.x)};
      }
      if (!in_range(value.x, min, max, open_min, open_max)) {
        return {range_text(min, max, open_min, open_max) + ", got " + number_text(value.x)};
      }
      return {};
    case FieldKind::whole:
      if (!(value.x == std::floor(value.x)) || !in_range(value.x, min, max, false, false)) {
        return {"must be a whole number from " + number_text(min) + " to " + number_text(max) +
                ", got " + number_text(value.x)};
      }
      return {};
    case FieldKind::flag:
      if (value.x != 0.0 && value.x != 1.0) return {"must be on or off"};
      return {};
    case FieldKind::map:
      return map_problem(value.map);
    case FieldKind::choice:
      if (!(value.x == std::floor(value.x)) || value.x < 0.0 ||
          value.x >= static_cast<double>(choices.size())) {
        std::string names;
        for (const char* name : choices) names += (names.empty() ? "" : ", ") + std::string(name);
        return {"must be one of " + names};
      }
      return {};
  }
  return {};
}

std::string field_text(FieldKind kind, const std::vector<const char*>& choices,
                       const FieldValue& value) {
  switch (kind) {
    case FieldKind::colour:
    case FieldKind::vector: {
      char text[96];
      std::snprintf(text, sizeof text, "%g %g %g", value.v.x, value.v.y, value.v.z);
      return text;
    }
    case FieldKind::number:
    case FieldKind::whole:
      return number_text(value.x);
    case FieldKind::flag:
      return value.x != 0.0 ? "on" : "off";
    case FieldKind::map:
      return value.map.named() ? value.map.file : "none";
    case FieldKind::choice: {
      const int index = static_cast<int>(value.x);
      return index >= 0 && index < static_cast<int>(choices.size()) ? choices[index] : "?";
    }
  }
  return "?";
}

}  // namespace gloss
