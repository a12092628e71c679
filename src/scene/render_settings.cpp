#include "scene/render_settings.h"

#include "scene/fields/fields.h"

namespace gloss {

namespace {
// The names of a choice field of the render table: the one place they are spelled.
const std::vector<const char*>& choice_names(const char* key) {
  return find_field(render_fields(), key)->choices;
}

template <class E>
bool parse_choice(const char* key, const std::string& name, E& out) {
  const int index = choice_index(*find_field(render_fields(), key), name);
  if (index < 0) return false;
  out = static_cast<E>(index);
  return true;
}
}  // namespace

const char* to_string(ShadingModel model) {
  return choice_names("model").at(static_cast<std::size_t>(model));
}

bool parse_shading_model(const std::string& name, ShadingModel& model) {
  return parse_choice("model", name, model);
}

const char* to_string(PowMode mode) {
  return choice_names("pow").at(static_cast<std::size_t>(mode));
}

bool parse_pow_mode(const std::string& name, PowMode& mode) {
  return parse_choice("pow", name, mode);
}

const char* to_string(Sampling sampling) {
  return choice_names("sampling").at(static_cast<std::size_t>(sampling));
}

bool parse_sampling(const std::string& name, Sampling& sampling) {
  return parse_choice("sampling", name, sampling);
}

const char* to_string(ToneCurve tone) {
  return choice_names("tone").at(static_cast<std::size_t>(tone));
}

bool parse_tone_curve(const std::string& name, ToneCurve& tone) {
  return parse_choice("tone", name, tone);
}

}  // namespace gloss
