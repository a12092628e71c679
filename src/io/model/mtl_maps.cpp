#include "io/model/mtl_maps.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "base/text/ascii.h"
#include "io/json/field_json.h"

namespace gloss {

namespace {

struct Keyword {
  const char* name;  // lower case
  MapSlot slot;
};
constexpr Keyword kKeywords[] = {
    {"map_kd", MapSlot::diffuse},  {"map_ka", MapSlot::ambient},   {"map_ks", MapSlot::specular},
    {"map_ke", MapSlot::emission}, {"map_ns", MapSlot::shininess}, {"map_d", MapSlot::opacity},
    {"bump", MapSlot::bump},       {"map_bump", MapSlot::bump},    {"norm", MapSlot::normal},
    {"map_kn", MapSlot::normal},
};
constexpr const char* kUnread[] = {"refl",   "disp",   "decal",   "map_tr",   "map_pr",
                                   "map_pm", "map_ps", "map_aat", "map_refl", "map_disp"};

// Arguments each option takes: (least, most) numbers or one word.
struct Option {
  const char* name;
  int least, most;  // numbers; most 0: one word (on/off, a channel, a type)
  bool honoured;
};
constexpr Option kOptions[] = {
    {"-o", 1, 3, true},      {"-s", 1, 3, true},       {"-clamp", 0, 0, true},
    {"-bm", 1, 1, true},     {"-blendu", 0, 0, false}, {"-blendv", 0, 0, false},
    {"-boost", 1, 1, false}, {"-cc", 0, 0, false},     {"-imfchan", 0, 0, false},
    {"-mm", 1, 2, false},    {"-t", 1, 3, false},      {"-texres", 1, 1, false},
    {"-type", 0, 0, false},
};

bool number(const std::string& token, float& out) {
  if (token.empty()) return false;
  char* end = nullptr;
  const double value = std::strtod(token.c_str(), &end);
  if (end != token.c_str() + token.size()) return false;
  out = static_cast<float>(value);
  return std::isfinite(out);
}

std::vector<std::string> words(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

// One map statement's options and file; false (with a reason) when it has no file name.
bool read_statement(const std::vector<std::string>& w, MtlMapStatement& s, std::string& reason) {
  std::size_t i = 1;
  while (i < w.size() && w[i].size() > 1 && w[i][0] == '-') {
    const std::string name = ascii_lower(w[i]);
    const Option* option = nullptr;
    for (const Option& o : kOptions) {
      if (name == o.name) option = &o;
    }
    if (option == nullptr) break;  // a file name starting with '-'
    std::string written = w[i++];
    float values[3] = {0.0f, 0.0f, 0.0f};
    int n = 0;
    if (option->most == 0) {
      if (i >= w.size()) break;
      const std::string arg = ascii_lower(w[i]);
      written += " " + w[i++];
      if (name == "-clamp") {
        const Wrap wrap = arg == "on" ? Wrap::clamp : Wrap::repeat;
        s.settings.wrap = {wrap, wrap};
      }
    } else {
      // Numbers, as many as the option takes and the line gives; what follows is the file.
      while (n < option->most && i + 1 < w.size() && number(w[i], values[n])) {
        written += " " + w[i++];
        ++n;
      }
      if (n < option->least) {
        reason = "option " + name + " needs a number";
        return false;
      }
      if (name == "-o") s.settings.offset = {values[0], n > 1 ? values[1] : 0.0f};
      if (name == "-s") s.settings.scale = {values[0], n > 1 ? values[1] : 1.0f};
      if (name == "-bm") s.bump_scale = values[0];
    }
    if (!option->honoured) s.ignored.push_back(written);
  }
  std::string file;
  for (; i < w.size(); ++i) file += (file.empty() ? "" : " ") + w[i];
  s.file = portable_path(file);
  if (s.file.empty()) {
    reason = "no file name";
    return false;
  }
  return true;
}

}  // namespace

bool mtl_map_slot(const std::string& keyword, MapSlot& slot) {
  const std::string k = ascii_lower(keyword);
  for (const Keyword& known : kKeywords) {
    if (k == known.name) {
      slot = known.slot;
      return true;
    }
  }
  return false;
}

bool is_unread_mtl_map(const std::string& keyword) {
  const std::string k = ascii_lower(keyword);
  return std::find(std::begin(kUnread), std::end(kUnread), k) != std::end(kUnread);
}

std::string portable_path(std::string path) {
  std::replace(path.begin(), path.end(), '\\', '/');
  while (path.size() > 2 && path.compare(0, 2, "./") == 0) path.erase(0, 2);
  return path;
}

std::map<std::string, std::vector<MtlMapStatement>> read_mtl_maps(
    const std::string& text, std::vector<std::string>& problems) {
  std::map<std::string, std::vector<MtlMapStatement>> out;
  std::string material;
  std::istringstream in(text);
  int number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const std::size_t hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    const std::vector<std::string> w = words(line);
    if (w.empty()) continue;
    if (w[0] == "newmtl") {
      material.clear();
      for (std::size_t i = 1; i < w.size(); ++i) material += (i > 1 ? " " : "") + w[i];
      continue;
    }
    MtlMapStatement s;
    if (!mtl_map_slot(w[0], s.slot)) continue;
    s.keyword = w[0];
    s.line = number;
    std::string reason;
    if (!read_statement(w, s, reason)) {
      problems.push_back("line " + std::to_string(number) + ": " + w[0] + ": " + reason);
      continue;
    }
    out[material].push_back(std::move(s));
  }
  return out;
}

std::string mtl_map_line(MapSlot slot, const TextureMap& map, float bump_scale) {
  static const char* const keywords[kMapSlots] = {"map_Kd", "map_Ka", "map_Ks", "map_Ke",
                                                  "map_Ns", "map_d",  "norm",   "bump"};
  std::string line = keywords[static_cast<int>(slot)];
  if (slot == MapSlot::bump && bump_scale != 1.0f) line += " -bm " + float_text(bump_scale);
  if (map.wrap[0] == Wrap::clamp && map.wrap[1] == Wrap::clamp) line += " -clamp on";
  if (map.offset != glm::vec2(0.0f)) {
    line += " -o " + float_text(map.offset.x) + " " + float_text(map.offset.y);
  }
  if (map.scale != glm::vec2(1.0f)) {
    line += " -s " + float_text(map.scale.x) + " " + float_text(map.scale.y);
  }
  return line + " " + map.file;
}

}  // namespace gloss
