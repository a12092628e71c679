#include "engine/change_class.h"

#include "engine/render_plan.h"

namespace gloss {

ChangeClass classify_change(const Scene& before, const Scene& after) {
  return classify_change(before, after, diff_scenes(before, after));
}

ChangeClass classify_change(const Scene& before, const Scene& after, const SceneDiff& diff) {
  ChangeClass change = diff.change;
  // A different plan (a light or term switched on or off) changes what the cache holds.
  if (change < ChangeClass::light && make_render_plan(before) != make_render_plan(after)) {
    change = ChangeClass::light;
  }
  // Under an environment the specular term's factors depend on the exponent and the model.
  if (change == ChangeClass::exponent && make_render_plan(after).environment) {
    change = ChangeClass::environment;
  }
  // Under a shininess map the energy normalisation varies per sample (power_lanes.h
  // ScaledExponent): the switch rebuilds the per-pixel factors.
  if (change == ChangeClass::shade &&
      before.render.energy_normalize != after.render.energy_normalize &&
      make_render_plan(after).textures.alpha) {
    change = ChangeClass::exponent;
  }
  if (change == ChangeClass::none && diff.any) change = ChangeClass::shade;
  return change;
}

bool changes_sky(const Scene& before, const Scene& after, ChangeClass change) {
  return change == ChangeClass::full || before.environment.map != after.environment.map ||
         before.environment.rotation != after.environment.rotation;
}

}  // namespace gloss
