#include "io/model/model_maps.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <utility>

#include "base/error.h"
#include "base/memory_budget.h"
#include "base/text/ascii.h"
#include "io/image/texture_reader.h"
#include "io/model/map_reading.h"
#include "io/model/mtl_maps.h"
#include "texture/mip_pyramid.h"
#include "texture/texel_image.h"

namespace gloss {

namespace fs = std::filesystem;

namespace {

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The MTL files an OBJ's `mtllib` lines name: the rest of the line when that is a file (names
// with spaces), else each word.
std::vector<std::string> mtl_libraries(const std::string& obj_path, const std::string& dir) {
  std::vector<std::string> out;
  std::ifstream in(obj_path, std::ios::binary);  // line by line: the file may be large
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const std::size_t start = line.find_first_not_of(" \t");
    if (start == std::string::npos || line.compare(start, 7, "mtllib ") != 0) continue;
    std::string rest = line.substr(start + 7);
    rest.erase(0, rest.find_first_not_of(" \t"));
    rest.erase(rest.find_last_not_of(" \t") + 1);
    rest = portable_path(rest);
    // The error_code form: a name the file system refuses (too long, say) is no file, not a
    // throw out of the model's reading (found by fuzz_obj).
    std::error_code error;
    if (fs::exists(fs::path(dir) / rest, error)) {
      out.push_back(rest);
      continue;
    }
    std::istringstream words(rest);
    for (std::string word; words >> word;) out.push_back(word);
  }
  return out;
}

}  // namespace

void ModelMapReader::unusable(const std::string& material, const std::string& what) {
  const std::string line = "material '" + material + "': " + what;
  model.unused.push_back(line);
  model.warnings.push_back(model_path + ": " + line);
}

std::shared_ptr<const Texture> ModelMapReader::read_file(const std::string& material,
                                                         const std::string& path, bool colour,
                                                         std::string& used_path) {
  used_path = portable_path(path);
  fs::path full = fs::path(model_dir) / used_path;
  std::error_code error;
  if (!fs::is_regular_file(full, error)) {
    const std::string name = fs::path(used_path).filename().string();
    if (!name.empty() && fs::is_regular_file(fs::path(model_dir) / name, error)) {
      used_path = name;
      full = fs::path(model_dir) / name;
    } else {
      unusable(material, "image '" + path + "' not found; left out");
      return nullptr;
    }
  }
  try {
    bool cached = false;
    auto texture = read_texture(full.string(), colour ? ImageData::colour : ImageData::linear,
                                budget > used ? budget - used : 1, &cached);
    if (!cached) used += texture->bytes();
    return texture;
  } catch (const InputError& e) {
    unusable(material,
             std::string("image '") + path + "' cannot be used (" + e.message() + "); left out");
  }
  return nullptr;
}

std::shared_ptr<const Texture> ModelMapReader::read_embedded(const std::string& material,
                                                             const std::string& name, bool colour) {
  const auto it = std::find_if(model.embedded.begin(), model.embedded.end(),
                               [&](const ModelEmbeddedImage& i) { return i.name == name; });
  if (it == model.embedded.end() || it->bytes.empty()) {
    unusable(material, "image " + name + " inside the file is missing or not a PNG or JPEG");
    return nullptr;
  }
  try {
    ImageReadOptions options;
    options.data = colour ? ImageData::colour : ImageData::linear;
    options.budget_bytes = budget > used ? budget - used : 1;
    options.extra_bytes_per_pixel = kPyramidBytesPerTexel;
    ImageFileInfo info;
    const std::string source = model_path + "#" + name;
    FloatImage image = read_image_bytes(it->bytes, source, options, &info);
    auto texture = texture_from_image(std::move(image), source, info);
    used += texture->bytes();
    return texture;
  } catch (const InputError& e) {
    unusable(material,
             "image " + name + " inside the file cannot be used (" + e.message() + "); left out");
  }
  return nullptr;
}

std::shared_ptr<const Texture> ModelMapReader::make(
    const std::string& material, const std::string& what, int width, int height, int channels,
    const std::function<glm::vec4(float, float)>& texel) {
  const std::uint64_t bytes = pyramid_bytes(width, height, channels);
  if (used + bytes > budget) {
    unusable(material, what + " of " + std::to_string(width) + "x" + std::to_string(height) +
                           " texels does not fit the memory budget; left out");
    return nullptr;
  }
  // At each texel's centre, in map coordinates (v up).
  FloatImage image = texel_image(width, height, channels, [&](int i, int j) {
    return texel((i + 0.5f) / width, 1.0f - (j + 0.5f) / height);
  });
  ImageFileInfo info;
  info.format = "made by gloss";
  info.bits = 32;
  auto texture = texture_from_image(std::move(image), model_path + ": " + what, info);
  used += texture->bytes();
  return texture;
}

void read_obj_maps(ModelMapReader& reader) {
  for (const std::string& library : mtl_libraries(reader.model_path, reader.model_dir)) {
    const fs::path mtl = fs::path(reader.model_dir) / library;
    std::error_code error;
    if (!fs::is_regular_file(mtl, error)) continue;  // assimp has said so already
    std::vector<std::string> problems;
    const auto statements = read_mtl_maps(read_text(mtl.string()), problems);
    for (const std::string& problem : problems) {
      reader.model.unused.push_back(library + " " + problem);
      reader.model.warnings.push_back(mtl.string() + ": " + problem);
    }
    const std::string mtl_dir = fs::path(library).parent_path().generic_string();
    for (std::size_t m = 0; m < reader.model.materials.size(); ++m) {
      const std::string& name = reader.model.material_names[m];
      const auto it = statements.find(name);
      if (it == statements.end()) continue;
      Material& material = reader.model.materials[m];
      for (const MtlMapStatement& s : it->second) {
        for (const std::string& option : s.ignored) {
          reader.unusable(name, s.keyword + " option '" + option + "' not used");
        }
        TextureMap map = s.settings;
        const std::string relative =
            mtl_dir.empty() ? s.file : (fs::path(mtl_dir) / s.file).generic_string();
        map.texture = reader.read_file(name, relative, is_colour_map(s.slot), map.file);
        if (!map.texture) continue;
        material.map(s.slot) = std::move(map);
        if (s.slot == MapSlot::bump) material.bump_scale = s.bump_scale;
      }
    }
  }
}

void read_model_maps(const std::string& path, Model& model, const ModelOptions& options) {
  ModelMapReader reader{
      path, fs::path(path).parent_path().string(), model,
      options.map_budget_bytes > 0 ? options.map_budget_bytes : memory_budget_bytes()};
  const std::string ext = lower_extension(path);
  if (ext == ".obj") read_obj_maps(reader);
  if (ext == ".gltf" || ext == ".glb") read_gltf_maps(reader);
  model.map_bytes = reader.used;
}

std::string model_map_reference(const std::string& model, const std::string& material,
                                MapSlot slot) {
  return model + "#" + material + "/" + to_string(slot);
}

void rename_map_files(std::vector<Material>& materials,
                      const std::function<void(std::string& name, bool model_part)>& rename) {
  for (Material& material : materials) {
    for (int s = 0; s < kMapSlots; ++s) {
      const auto slot = static_cast<MapSlot>(s);
      const TextureMap& map = std::as_const(material).map(slot);  // reads without copying
      if (!map.named()) continue;
      std::string file = map.file;
      std::string model, model_material;
      MapSlot model_slot;
      if (split_model_map_reference(file, model, model_material, model_slot)) {
        rename(model, true);
        file = model_map_reference(model, model_material, model_slot);
      } else {
        rename(file, false);
      }
      if (file != map.file) material.map(slot).file = file;
    }
  }
}

void name_maps_for_scene(std::vector<Material>& materials, const std::string& model_file) {
  const fs::path folder = fs::path(model_file).parent_path();
  rename_map_files(materials, [&](std::string& name, bool model_part) {
    name = model_part ? model_file : (folder / name).lexically_normal().generic_string();
  });
}

bool split_model_map_reference(const std::string& file, std::string& model, std::string& material,
                               MapSlot& slot) {
  const std::string low = ascii_lower(file);
  std::size_t at = std::string::npos;
  for (const char* ext : {".obj#", ".gltf#", ".glb#"}) {
    const std::size_t found = low.find(ext);
    if (found != std::string::npos) at = std::min(at, found + std::string(ext).size() - 1);
  }
  if (at == std::string::npos) return false;
  const std::size_t slash = file.rfind('/');
  if (slash == std::string::npos || slash < at) return false;
  const std::string slot_name = file.substr(slash + 1);
  for (int s = 0; s < kMapSlots; ++s) {
    if (slot_name != to_string(static_cast<MapSlot>(s))) continue;
    model = file.substr(0, at);
    material = file.substr(at + 1, slash - at - 1);
    slot = static_cast<MapSlot>(s);
    return true;
  }
  return false;
}

}  // namespace gloss
