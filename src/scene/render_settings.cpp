#include "scene/render_settings.h"

namespace gloss {

const char* to_string(ShadingModel model) {
  switch (model) {
    case ShadingModel::phong:
      return "phong";
    case ShadingModel::blinn_phong:
      return "blinn-phong";
  }
  return "unknown";
}

bool parse_shading_model(const std::string& name, ShadingModel& model) {
  if (name == "phong") {
    model = ShadingModel::phong;
    return true;
  }
  if (name == "blinn-phong") {
    model = ShadingModel::blinn_phong;
    return true;
  }
  return false;
}

}  // namespace gloss
