// The object and material lines of scripts (issue 24), parsed into ObjectLineActions and, when
// they run, resolved against the document into commands (object_commands.h).
#include <string>

#include "base/text/text_distance.h"
#include "editor/model/document/new_objects.h"
#include "editor/model/script/script_tokens.h"

namespace gloss {

namespace {

const char* const kPrimitives[] = {"sphere", "quad", "box", "teapot"};

}  // namespace

ObjectRef parse_object_ref(Tokens& t) {
  const bool quoted = !t.done() && t.quoted[t.next];
  const std::string& w = t.word("object (an index or a name)");
  ObjectRef ref;
  const bool digits = !w.empty() && w.find_first_not_of("0123456789") == std::string::npos;
  if (digits && !quoted) {
    if (w.size() > 7) throw std::runtime_error("object index " + w + " is too large");
    ref.index = std::stoi(w);
  } else {
    ref.name = w;
  }
  return ref;
}

namespace {

ObjectLineAction parse_add(Tokens& t) {
  ObjectLineAction a;
  const std::string& what = t.word("what to add (sphere, quad, box, teapot or model PATH)");
  if (what == "model") {
    a.verb = ObjectLineAction::Verb::add_model;
    a.text = t.word("model path");
    return a;
  }
  for (int i = 0; i < 4; ++i) {
    if (what == kPrimitives[i]) {
      a.type = static_cast<ObjectType>(i);  // sphere, quad, box, teapot: ObjectType's order
      return a;
    }
  }
  throw std::runtime_error("object add takes sphere, quad, box, teapot or 'model PATH', got '" +
                           what + "'");
}

ObjectLineAction parse_object(Tokens& t) {
  if (!t.done() && t.words[t.next] == "add" && !t.quoted[t.next]) {
    ++t.next;
    return parse_add(t);
  }
  ObjectLineAction a;
  a.object = parse_object_ref(t);
  const std::string& verb = t.word("what to do (move, rotate, scale, pivot, delete, ...)");
  using Verb = ObjectLineAction::Verb;
  const std::pair<const char*, Verb> plain[] = {{"delete", Verb::remove},
                                                {"duplicate", Verb::duplicate},
                                                {"hide", Verb::hide},
                                                {"show", Verb::show},
                                                {"solo", Verb::solo}};
  for (const auto& [word, v] : plain) {
    if (verb == word) {
      a.verb = v;
      return a;
    }
  }
  if (verb == "name") {
    a.verb = Verb::name;
    a.text = t.word("the new name");
    return a;
  }
  // The transform's fields: `move` is the translate; the others go by their keys.
  const std::string key = verb == "move" ? "translate" : verb;
  const Field<ObjectTransform>* field = find_field(transform_fields(), key);
  if (field == nullptr) {
    throw std::runtime_error(
        "object OBJECT takes move, rotate, scale, pivot, delete, duplicate, "
        "hide, show, solo or name, got '" +
        verb + "'");
  }
  a.verb = Verb::field;
  a.field = SetField{FieldPart::transform, 0, field->key, parse_value(t, *field)};
  return a;
}

}  // namespace

ScriptAction parse_object_line(Tokens& t) {
  const std::string& verb = t.words[0];
  if (verb == "object") return parse_object(t);
  if (verb == "save") return SaveAction{t.word("scene path")};
  if (verb == "browse") {
    const std::string& what = t.word("what to browse for");
    for (const char* known : {"save-scene", "save-material", "save-materials", "export-glsl",
                              "open-scene", "add-model"}) {
      if (what == known) return BrowseAction{what};
    }
    throw std::runtime_error(
        "browse takes save-scene, save-material, save-materials, export-glsl, open-scene or "
        "add-model, got '" +
        what + "'");
  }
  if (verb == "gizmo") {
    const std::string& mode = t.word("gizmo mode");
    if (mode == "move") return GizmoAction{GizmoMode::move};
    if (mode == "rotate") return GizmoAction{GizmoMode::rotate};
    if (mode == "scale") return GizmoAction{GizmoMode::scale};
    throw std::runtime_error("gizmo takes move, rotate or scale, got '" + mode + "'");
  }
  ObjectLineAction a;
  if (verb == "material") {
    const std::string& what = t.word("material action");
    if (what != "rename")
      throw std::runtime_error("material takes 'rename OLD NEW', got '" + what + "'");
    a.verb = ObjectLineAction::Verb::rename_material;
    a.text = t.word("the material's name");
    a.text2 = t.word("its new name");
    return a;
  }
  a.verb = ObjectLineAction::Verb::assign;  // assign OBJECT MATERIAL
  a.object = parse_object_ref(t);
  a.text = t.word("material name");
  return a;
}

int resolve_object(const Scene& scene, const ObjectRef& ref) {
  const int count = static_cast<int>(scene.objects.size());
  if (ref.index >= 0) {
    if (ref.index >= count) {
      throw CommandError("no object " + std::to_string(ref.index) + " (the scene has " +
                         std::to_string(count) + ")");
    }
    return ref.index;
  }
  const int found = find_object(scene, ref.name);
  if (found >= 0) return found;
  std::vector<std::string> names;
  for (const Object& o : scene.objects) names.push_back(o.name);
  throw CommandError("no object called '" + ref.name + "'" +
                     did_you_mean(nearest_words(ref.name, names, 3)));
}

Command object_line_command(const Scene& scene, const ObjectLineAction& line,
                            std::vector<std::string>* warnings) {
  using Verb = ObjectLineAction::Verb;
  if (line.verb == Verb::add) return primitive_objects(scene, line.type);
  if (line.verb == Verb::add_model) return model_objects(scene, line.text, warnings);
  if (line.verb == Verb::rename_material) return RenameMaterial{line.text, line.text2};
  const int object = resolve_object(scene, line.object);
  switch (line.verb) {
    case Verb::field: {
      SetField c = line.field;
      c.index = object;
      return c;
    }
    case Verb::remove:
      return DeleteObjects{{object}};
    case Verb::duplicate:
      return DuplicateObjects{{object}};
    case Verb::hide:
      return SetHidden{{object}, true};
    case Verb::show:
      return SetHidden{{object}, false};
    case Verb::solo:
      return SoloObjects{{object}};
    case Verb::name:
      return RenameObject{object, line.text};
    case Verb::preset:
      return ApplyPreset{object, line.text};
    case Verb::assign: {
      const int material = find_material(scene, line.text);
      if (material < 0) {
        throw CommandError("no material called '" + line.text + "'" +
                           did_you_mean(nearest_words(line.text, scene.material_names, 3)));
      }
      return AssignMaterial{{object}, material};
    }
    case Verb::add:
    case Verb::add_model:
    case Verb::rename_material:
      break;
  }
  throw CommandError("unknown object line");
}

}  // namespace gloss
