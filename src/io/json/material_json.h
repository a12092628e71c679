#pragma once
// A material as a JSON object, as in a scene's "materials" block: io's own, so the JSON library
// stays private to io (scene_loader.cpp, scene_json_writer.cpp, material_io.cpp).
#include <string>

#include <nlohmann/json.hpp>

#include "scene/material.h"

namespace gloss {

// The JSON object of a material: its preset, if any, then every field of its table.
nlohmann::ordered_json material_to_json(const Material& material);
// Parses and validates a material object: {"preset": NAME, ...overrides} or explicit fields.
// file and field name the place for errors (InputError).
Material material_from_json(const nlohmann::json& value, const std::string& file,
                            const std::string& field);

}  // namespace gloss
