#include "editor/model/measure/pixel_report.h"

#include <cstdio>

namespace gloss {

namespace {

// 9 significant digits: a float's value survives the round trip, and the double reference's
// figures read to well below the contract's 1e-4.
void add_value(std::string& out, const std::string& name, double value) {
  char line[160];
  std::snprintf(line, sizeof line, "%s %.9g\n", name.c_str(), value);
  out += line;
}

void add_rgb(std::string& out, const std::string& name, const glm::dvec3& c) {
  char line[200];
  std::snprintf(line, sizeof line, "%s %.9g %.9g %.9g\n", name.c_str(), c.x, c.y, c.z);
  out += line;
}

}  // namespace

std::string pixel_report(const PixelBreakdown& b) {
  std::string out = "pixel " + std::to_string(b.x) + " " + std::to_string(b.y) + " " +
                    std::to_string(b.width) + "x" + std::to_string(b.height) + "\n";
  if (!b.hit) {
    out += "object none\nmaterial none\n";
  } else {
    out +=
        "object " + (b.object_name.empty() ? "#" + std::to_string(b.object) : b.object_name) + "\n";
    out += "material " +
           (b.material_name.empty() ? "#" + std::to_string(b.material) : b.material_name) + "\n";
    add_value(out, "alpha", b.alpha);
    add_value(out, "energy_factor", b.energy_factor);
  }
  add_rgb(out, "total", b.total);
  add_rgb(out, "emissive", b.emissive);
  add_rgb(out, "ambient", b.ambient);
  add_rgb(out, "diffuse", b.diffuse);
  add_rgb(out, "specular", b.specular);
  if (b.textured) {  // the maps: the hit's (u, v), footprints, each map's level and texel
    char line[200];
    std::snprintf(line, sizeof line, "uv0 %.9g %.9g\nuv1 %.9g %.9g\n", b.uv[0].x, b.uv[0].y,
                  b.uv[1].x, b.uv[1].y);
    out += line;
    add_value(out, "footprint0", b.footprint[0]);
    add_value(out, "footprint1", b.footprint[1]);
    for (int s = 0; s < kMapSlots; ++s) {
      const MapReading& m = b.maps[s];
      if (!m.present) continue;
      const std::string name = std::string("map.") + to_string(static_cast<MapSlot>(s));
      add_value(out, name + ".level", m.level);
      std::snprintf(line, sizeof line, "%s.texel %.9g %.9g %.9g %.9g\n", name.c_str(), m.texel.x,
                    m.texel.y, m.texel.z, m.texel.w);
      out += line;
    }
  }
  if (b.environment.present) {
    // Exact integrals with their error bounds (shadows off) or estimates with their standard
    // errors (shadows on: then also the terms without shadows and the visible share).
    const EnvironmentBreakdown& e = b.environment;
    add_rgb(out, "environment.diffuse", e.diffuse);
    add_rgb(out, "environment.diffuse_error", e.diffuse_error);
    add_rgb(out, "environment.specular", e.specular);
    add_rgb(out, "environment.specular_error", e.specular_error);
    if (e.estimated) {
      add_rgb(out, "environment.unshadowed_diffuse", e.unshadowed_diffuse);
      add_rgb(out, "environment.unshadowed_specular", e.unshadowed_specular);
    }
    add_value(out, "environment.visibility", e.visibility);
  }
  for (std::size_t i = 0; i < b.lights.size(); ++i) {
    const LightBreakdown& l = b.lights[i];
    const std::string prefix = "light" + std::to_string(i) + ".";
    add_value(out, prefix + "ndl", l.ndl);
    add_value(out, prefix + "c", l.cosine);
    add_value(out, prefix + "c_alpha", l.cosine_power);
    add_value(out, prefix + "attenuation", l.attenuation);
    add_value(out, prefix + "spot", l.spot);
    add_value(out, prefix + "visibility", l.visibility);
    add_rgb(out, prefix + "diffuse", l.diffuse);
    add_rgb(out, prefix + "specular", l.specular);
  }
  return out;
}

}  // namespace gloss
