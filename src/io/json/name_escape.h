#pragma once
// Names are bytes: an MTL file, a file name or an older tool may hand gloss a material name such
// as "Terrain\xE6k" (Latin-1) that is not UTF-8, and JSON text must be. In the name strings of
// gloss's JSON files (object and material names, material references, mesh file and group, the
// recovery file's scene path) the four characters \xHH (backslash, x, two hex digits; the
// backslash is written \\ in JSON text) stand for the byte 0xHH. Writers escape every byte that
// is not part of well-formed UTF-8 this way, and a backslash that would otherwise start such an
// escape as \x5C; readers undo it. So load -> save -> load gives the same bytes for any name
// (docs/spec/scene-and-cli.md, "Names").
#include <string>

namespace gloss {

// name as valid UTF-8 text for a JSON string (uppercase hex digits).
std::string escape_name(const std::string& name);

// The bytes a JSON name string stands for: every \xHH (either case) becomes the byte 0xHH.
std::string unescape_name(const std::string& text);

}  // namespace gloss
