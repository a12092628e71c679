#pragma once
// The map statements of Wavefront MTL files, read here rather than through assimp: assimp 5.2.5
// maps the keywords but drops the -o and -s options, and a short `-s 2 2 file.png` makes it take
// "2" for the file name. Keywords (any case): map_Kd, map_Ka, map_Ks, map_Ke, map_Ns, map_d,
// bump and map_bump (with -bm), norm; options -o and -s (u [v [w]]: the offset and scale of
// (u, v)), -clamp on|off (clamp, else repeat), -bm (bump_scale); options gloss cannot honour
// (-blendu, -blendv, -boost, -cc, -imfchan, -mm, -t, -texres, -type) are skipped with their
// arguments and reported. A file name is the rest of the line (names may hold spaces), with
// Windows separators (`.\tex\wood.jpg`) turned into '/'.
#include <map>
#include <string>
#include <vector>

#include "scene/texture_map.h"

namespace gloss {

struct MtlMapStatement {
  MapSlot slot = MapSlot::diffuse;
  std::string keyword;               // as written
  std::string file;                  // the image, '/'-separated, "./" dropped
  TextureMap settings;               // wrap, offset, scale from the options (no file, no texture)
  float bump_scale = 1.0f;           // -bm
  std::vector<std::string> ignored;  // options gloss does not honour, as written
  int line = 0;
};

// The map keyword's slot, or false for a keyword that is no map gloss reads.
bool mtl_map_slot(const std::string& keyword, MapSlot& slot);

// Whether a keyword names a map gloss does not read (refl, disp, decal, map_Pr ...).
bool is_unread_mtl_map(const std::string& keyword);

// The map statements of an MTL text by material (newmtl) name, in file order. Statements that
// cannot be read (no file name, a bad number) are reported in problems with their line.
std::map<std::string, std::vector<MtlMapStatement>> read_mtl_maps(
    const std::string& text, std::vector<std::string>& problems);

// A path as a model file writes it, with '\' turned into '/' and leading "./" dropped.
std::string portable_path(std::string path);

// The MTL statement for a map of slot (what save_mtl writes), or "" for a slot MTL has no
// keyword for.
std::string mtl_map_line(MapSlot slot, const TextureMap& map, float bump_scale);

}  // namespace gloss
