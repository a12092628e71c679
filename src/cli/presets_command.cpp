// gloss-cli presets: the 24 OpenGL/VRML material presets as a table, in the table's order.
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>

#include "cli/commands.h"
#include "io/material/preset_table.h"

namespace gloss {

namespace {

std::string rgb_text(const glm::vec3& c) {
  char text[48];
  std::snprintf(text, sizeof text, "%.3f %.3f %.3f", c.x, c.y, c.z);
  return text;
}

// The shortest text that reads back as exactly value: the table's own digits ("0.6", not
// "0.60000002").
std::string shortest_text(float value) {
  char text[32] = {};
  for (int digits = 1; digits <= 9; ++digits) {
    std::snprintf(text, sizeof text, "%.*g", digits, static_cast<double>(value));
    if (std::strtof(text, nullptr) == value) break;
  }
  return text;
}

void run_presets() {
  char line[256];
  std::snprintf(line, sizeof line, "%-16s %-19s  %-19s  %-19s  %-13s  %s", "name", "ka", "kd", "ks",
                "shininess_raw", "exponent");
  std::cout << line << "\n";
  for (const Preset& preset : preset_table()) {
    const Material& m = preset.material;
    // The exponent is shininess_raw x 128, as teapots.c passes it to GL_SHININESS.
    std::snprintf(line, sizeof line, "%-16s %-19s  %-19s  %-19s  %-13s  %.6g", preset.name.c_str(),
                  rgb_text(m.ambient).c_str(), rgb_text(m.diffuse).c_str(),
                  rgb_text(m.specular).c_str(), shortest_text(preset.shininess_raw).c_str(),
                  static_cast<double>(m.shininess));
    std::cout << line << "\n";
  }
}

}  // namespace

void add_presets_command(CLI::App& app) {
  CLI::App* sub = app.add_subcommand(
      "presets", "List the 24 material presets: ka, kd, ks, shininess_raw and exponent (x128)");
  sub->callback([] { run_presets(); });
}

}  // namespace gloss
