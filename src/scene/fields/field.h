#pragma once
// One editable field of a document struct, declared once in a table (scene/fields/fields.h): its
// JSON key, label, unit, valid range, change class, getter and setter. The scene reader and writer,
// validation, the editor's set-field command, the script language, the panels and the change
// classes all iterate over the tables, so a new field is its struct member, its table row and
// the shading code that uses it.
#include <cmath>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include "scene/fields/change.h"
#include "scene/texture_map.h"

namespace gloss {

enum class FieldKind {
  colour,  // linear RGB, every component finite and >= 0
  vector,  // three finite components, each within [min, max]
  number,  // one finite float within [min, max] (bounds exclusive when open_min / open_max)
  whole,   // a whole number within [min, max]
  flag,    // true or false
  choice,  // one of the names in choices
  map,     // an image map: a file and how (u, v) reach it (scene/texture_map.h)
};

// A field's value whatever its kind: colours and vectors in v; numbers, whole numbers, flags
// (0 or 1) and choices (the index into choices) in x; maps in map. A double holds every float,
// every int and every uint32_t exactly.
struct FieldValue {
  glm::vec3 v{0.0f};
  double x = 0.0;
  TextureMap map;
};

inline FieldValue vec3_value(const glm::vec3& v) {
  FieldValue value;
  value.v = v;
  return value;
}
inline FieldValue number_value(double x) {
  FieldValue value;
  value.x = x;
  return value;
}

inline FieldValue map_value(TextureMap map) {
  FieldValue value;
  value.map = std::move(map);
  return value;
}

inline bool operator==(const FieldValue& a, const FieldValue& b) {
  return a.v == b.v && a.x == b.x && a.map == b.map;
}
inline bool operator!=(const FieldValue& a, const FieldValue& b) {
  return !(a == b);
}

template <class S>
struct Field {
  const char* key = "";    // JSON key and script word
  const char* label = "";  // panel label
  const char* help = "";   // one line for tooltips and help texts; units go here
  FieldKind kind = FieldKind::number;
  double min = -std::numeric_limits<double>::infinity();  // valid range (of each component)
  double max = std::numeric_limits<double>::infinity();
  bool open_min = false, open_max = false;  // bounds excluded
  double ui_min = 0.0, ui_max = 1.0;        // the panels' slider or drag range
  bool ui_log = false;                      // slider on a logarithmic scale
  ChangeClass change = ChangeClass::full;   // what an edit of it invalidates
  bool required = false;                    // must be given in a scene file
  bool one_number = false;                  // a vector that one number may give (s for s, s, s)
  std::vector<const char*> choices;         // names of a choice field, in enum order
  FieldValue (*get)(const S&) = nullptr;
  void (*set)(S&, const FieldValue&) = nullptr;
  // Whether the value's other fields make this one matter (a light's type: a directional light
  // has no position); null: always. A field that does not apply is kept and ignored: not
  // required, not shown, written only when it differs from its default.
  bool (*applies)(const S&) = nullptr;

  bool applies_to(const S& s) const { return applies == nullptr || applies(s); }

  // Builder steps for the tables' rows.
  Field& range(double lo, double hi) {
    min = lo;
    max = hi;
    return *this;
  }
  Field& open(bool lo, bool hi) {
    open_min = lo;
    open_max = hi;
    return *this;
  }
  Field& ui(double lo, double hi, bool log = false) {
    ui_min = lo;
    ui_max = hi;
    ui_log = log;
    return *this;
  }
  Field& invalidates(ChangeClass c) {
    change = c;
    return *this;
  }
  Field& needed() {
    required = true;
    return *this;
  }
  Field& explain(const char* text) {
    help = text;
    return *this;
  }
  Field& only_when(bool (*condition)(const S&)) {
    applies = condition;
    return *this;
  }
  Field& uniform_allowed() {
    one_number = true;
    return *this;
  }
};

template <class S>
using FieldTable = std::vector<Field<S>>;

// ---- rows ------------------------------------------------------------------------------------

template <class M>
struct MemberOf;
template <class S, class V>
struct MemberOf<V S::*> {
  using Struct = S;
};

// A glm::vec3 member as a colour or a vector.
template <auto Member>
Field<typename MemberOf<decltype(Member)>::Struct> vec3_field(FieldKind kind, const char* key,
                                                              const char* label) {
  using S = typename MemberOf<decltype(Member)>::Struct;
  Field<S> f;
  f.key = key;
  f.label = label;
  f.kind = kind;
  if (kind == FieldKind::colour) f.range(0.0, std::numeric_limits<double>::infinity());
  f.get = [](const S& s) {
    FieldValue value;
    value.v = s.*Member;
    return value;
  };
  f.set = [](S& s, const FieldValue& value) { s.*Member = value.v; };
  return f;
}

// A float, int, std::uint32_t or bool member as a number, a whole number or a flag.
template <auto Member>
Field<typename MemberOf<decltype(Member)>::Struct> scalar_field(FieldKind kind, const char* key,
                                                                const char* label) {
  using S = typename MemberOf<decltype(Member)>::Struct;
  Field<S> f;
  f.key = key;
  f.label = label;
  f.kind = kind;
  f.get = [](const S& s) {
    FieldValue value;
    value.x = static_cast<double>(s.*Member);
    return value;
  };
  f.set = [](S& s, const FieldValue& value) {
    using V = std::remove_reference_t<decltype(s.*Member)>;
    if constexpr (std::is_same_v<V, bool>) {
      s.*Member = value.x != 0.0;
    } else {
      s.*Member = static_cast<V>(value.x);
    }
  };
  return f;
}

// An enum member as a choice among names (in the enum's order, from 0).
template <auto Member>
Field<typename MemberOf<decltype(Member)>::Struct> choice_field(const char* key, const char* label,
                                                                std::vector<const char*> names) {
  using S = typename MemberOf<decltype(Member)>::Struct;
  Field<S> f;
  f.key = key;
  f.label = label;
  f.kind = FieldKind::choice;
  f.choices = std::move(names);
  f.range(0.0, static_cast<double>(f.choices.size()) - 1.0);
  f.get = [](const S& s) {
    FieldValue value;
    value.x = static_cast<double>(static_cast<int>(s.*Member));
    return value;
  };
  f.set = [](S& s, const FieldValue& value) {
    using V = std::remove_reference_t<decltype(s.*Member)>;
    s.*Member = static_cast<V>(static_cast<int>(value.x));
  };
  return f;
}

// One of a Material's maps (scene/material.h) as a map field.
template <class S, MapSlot Slot>
Field<S> map_field(const char* key, const char* label) {
  Field<S> f;
  f.key = key;
  f.label = label;
  f.kind = FieldKind::map;
  f.get = [](const S& s) { return map_value(s.map(Slot)); };
  f.set = [](S& s, const FieldValue& value) { s.map(Slot) = value.map; };
  return f;
}

// ---- lookups and checks ----------------------------------------------------------------------

// The field called key, or null.
template <class S>
const Field<S>* find_field(const FieldTable<S>& table, const std::string& key) {
  for (const Field<S>& f : table) {
    if (key == f.key) return &f;
  }
  return nullptr;
}

template <class S>
std::vector<std::string> field_keys(const FieldTable<S>& table) {
  std::vector<std::string> keys;
  for (const Field<S>& f : table) keys.emplace_back(f.key);
  return keys;
}

// The index of name among a choice field's names, or -1.
template <class S>
int choice_index(const Field<S>& field, const std::string& name) {
  for (std::size_t i = 0; i < field.choices.size(); ++i) {
    if (name == field.choices[i]) return static_cast<int>(i);
  }
  return -1;
}

// Why value is not valid for a field of this kind and range ("" when it is), and which
// component is wrong (-1: the value as a whole). The checks validation and commands share.
struct FieldProblem {
  std::string message;
  int component = -1;
};
FieldProblem field_problem(FieldKind kind, double min, double max, bool open_min, bool open_max,
                           const std::vector<const char*>& choices, const FieldValue& value);

template <class S>
FieldProblem field_problem(const Field<S>& field, const FieldValue& value) {
  return field_problem(field.kind, field.min, field.max, field.open_min, field.open_max,
                       field.choices, value);
}

// The value as scripts and labels write it: "0.5 0.25 1", "32", "on", "blinn-phong".
std::string field_text(FieldKind kind, const std::vector<const char*>& choices,
                       const FieldValue& value);

template <class S>
std::string field_text(const Field<S>& field, const FieldValue& value) {
  return field_text(field.kind, field.choices, value);
}

}  // namespace gloss
