#pragma once
// The field tables of scene/fields/fields.h in JSON: one reader and one writer for every field of
// every table, so the scene file, the materials file and the editor's recovery file read and write
// a field the same way. io's own (the JSON library stays private to io).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/scene/scene_json_reader.h"
#include "scene/fields/field.h"

namespace gloss {

// The shortest decimal (6 to 9 significant digits) that reads back as exactly f through
// strtod and a conversion to float, as every reader of gloss's files reads numbers; whole
// numbers are written without a fraction. Assumes the C numeric locale.
std::string float_text(float f);
// float_text as a JSON number (an integer for whole numbers).
nlohmann::json float_json(float f);

// One field's value from reader's key, parsed by kind: whole numbers are range-checked here,
// before anything is sized from them; other ranges are validation's (scene/fields/validation.h). A
// colour component of -0 reads as 0.
FieldValue read_field_value(const JsonObjectReader& reader, const std::string& key,
                            const std::string& label, FieldKind kind, double min, double max,
                            const std::vector<const char*>& choices);
nlohmann::json field_value_json(FieldKind kind, const std::vector<const char*>& choices,
                                const FieldValue& value);

// Sets every field of table that reader's object holds; a missing required field is an error
// where it applies (Field::applies, judged on the fields read before it: a light's `type` comes
// first in its table).
template <class S>
void read_fields(const JsonObjectReader& reader, const FieldTable<S>& table, S& out) {
  for (const Field<S>& f : table) {
    if (!reader.has(f.key)) {
      if (f.required && f.applies_to(out)) reader.required(f.key);  // "missing required field"
      continue;
    }
    if (f.one_number && reader.required(f.key).is_number()) {  // "scale": 2 for [2, 2, 2]
      f.set(out, vec3_value(glm::vec3(reader.number(f.key))));
      continue;
    }
    f.set(out, read_field_value(reader, f.key, f.label, f.kind, f.min, f.max, f.choices));
  }
}

// The fields of table whose values differ from those of defaults, in table order (optional
// blocks such as an object's transform, written only where they say something); a one_number
// vector with equal components as that number.
template <class S>
void write_changed_fields(const FieldTable<S>& table, const S& value, const S& defaults,
                          nlohmann::ordered_json& out) {
  for (const Field<S>& f : table) {
    const FieldValue v = f.get(value);
    if (v == f.get(defaults)) continue;
    if (f.one_number && v.v.x == v.v.y && v.v.y == v.v.z) {
      out[f.key] = float_json(v.v.x);
    } else {
      out[f.key] = field_value_json(f.kind, f.choices, v);
    }
  }
}

// Adds every field of table to out, in table order, except those that do not apply to value
// and hold their default (S{}'s): a point light's file keeps its old keys, and a spot switched
// to a point light keeps its cone for a switch back. Map fields without a map are left out.
template <class S>
void write_fields(const FieldTable<S>& table, const S& value, nlohmann::ordered_json& out) {
  for (const Field<S>& f : table) {
    if (!f.applies_to(value) && f.get(value) == f.get(S{})) continue;
    if (f.kind == FieldKind::map && !f.get(value).map.named()) continue;  // no map
    out[f.key] = field_value_json(f.kind, f.choices, f.get(value));
  }
}

// The keys of table, plus extra ones the caller reads itself.
template <class S>
std::vector<std::string> allowed_keys(const FieldTable<S>& table,
                                      std::vector<std::string> extra = {}) {
  for (const Field<S>& f : table) extra.emplace_back(f.key);
  return extra;
}

}  // namespace gloss
