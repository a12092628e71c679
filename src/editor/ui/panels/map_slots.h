#pragma once
// The Material panel's maps (docs/spec/shading.md, "Textures"): per slot a thumbnail, the file,
// Load... (the file browser, with the recent maps), Clear and the map's (u, v) scale, each edit
// one command through the field table's map fields.
#include <string>

#include "scene/material.h"

namespace gloss {

class Commands;
struct FileBrowser;
class MapThumbnails;

void draw_map_slots(Commands& commands, FileBrowser& browser, MapThumbnails& thumbnails, int object,
                    const Material& material, const std::string& start_folder);

}  // namespace gloss
