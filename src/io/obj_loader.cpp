#include "io/obj_loader.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include <tiny_obj_loader.h>

#include <glm/geometric.hpp>

#include "base/error.h"
#include "base/number_words.h"

namespace gloss {

namespace {

// OBJ statements split on spaces and tabs, as tinyobjloader reads them; "" for blank lines.
std::vector<std::string> split_words(const std::string& line) {
  std::vector<std::string> words;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    const std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
    if (i > start) words.push_back(line.substr(start, i - start));
  }
  return words;
}

bool parse_finite(const std::string& word) {
  float value;
  return parse_finite_float(word, value);
}

struct ElementCounts {
  long v = 0, vt = 0, vn = 0;
};

struct MaterialUse {
  std::string name;
  int line;
};

struct ObjScan {
  std::vector<MaterialUse> used_materials;  // every 'usemtl', in file order
  std::vector<std::string> material_files;  // the material libraries found on disk
  std::vector<std::string> warnings;
};

// One 'f' corner "v", "v/vt", "v//vn" or "v/vt/vn": every index must name an element that
// exists, 1-based, or negative relative to the elements defined so far (so_far). tinyobjloader
// does not check this and reads out of bounds, so it is checked here first.
void check_corner(const std::string& corner, const ElementCounts& so_far,
                  const ElementCounts& total, const std::string& path, int line) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (std::size_t slash; (slash = corner.find('/', start)) != std::string::npos;) {
    parts.push_back(corner.substr(start, slash - start));
    start = slash + 1;
  }
  parts.push_back(corner.substr(start));
  const char* names[3] = {"vertex", "texture coordinate", "normal"};
  const char* plurals[3] = {"vertices", "texture coordinates", "normals"};
  const long defined[3] = {so_far.v, so_far.vt, so_far.vn};
  const long available[3] = {total.v, total.vt, total.vn};
  if (parts.size() > 3) throw InputError(path, "malformed face corner '" + corner + "'", line);
  for (std::size_t k = 0; k < parts.size(); ++k) {
    if (k == 1 && parts.size() == 3 && parts[1].empty()) continue;  // "v//vn": no texture
    long index = 0;
    if (!parse_long(parts[k], index)) {
      throw InputError(path, "malformed face corner '" + corner + "'", line);
    }
    if (index == 0) {
      throw InputError(path, "index 0 in face corner '" + corner + "' (OBJ counts from 1)", line);
    }
    const bool in_range = index > 0 ? index <= available[k] : index >= -defined[k];
    if (!in_range) {
      throw InputError(path,
                       std::string(names[k]) + " index " + std::to_string(index) +
                           " out of range (" +
                           std::to_string(index > 0 ? available[k] : defined[k]) + " " +
                           plurals[k] + (index > 0 ? " in the file)" : " defined so far)"),
                       line);
    }
  }
}

// Checks what tinyobjloader would accept silently (vertices that are not numbers, out-of-range
// face indices, faces with fewer than three corners) and collects the material references.
ObjScan scan_obj(const std::string& text, const std::string& path) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  ElementCounts total;
  for (const std::string& line : lines) {
    const std::vector<std::string> words = split_words(line);
    if (words.empty()) continue;
    total.v += words[0] == "v";
    total.vt += words[0] == "vt";
    total.vn += words[0] == "vn";
  }

  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  ObjScan scan;
  ElementCounts so_far;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const int line = static_cast<int>(i) + 1;
    const std::vector<std::string> words = split_words(lines[i]);
    if (words.empty()) continue;
    const std::string& keyword = words[0];
    if (keyword == "v" || keyword == "vn") {
      if (words.size() < 4 || !parse_finite(words[1]) || !parse_finite(words[2]) ||
          !parse_finite(words[3])) {
        throw InputError(path, "'" + keyword + "' needs three finite numbers", line);
      }
      ++(keyword == "v" ? so_far.v : so_far.vn);
    } else if (keyword == "vt") {
      ++so_far.vt;
    } else if (keyword == "f") {
      if (words.size() < 4) throw InputError(path, "a face needs at least three corners", line);
      for (std::size_t k = 1; k < words.size(); ++k) {
        check_corner(words[k], so_far, total, path, line);
      }
    } else if (keyword == "usemtl" && words.size() >= 2) {
      scan.used_materials.push_back({words[1], line});
    } else if (keyword == "mtllib") {
      // tinyobjloader loads the first of the named files that exists.
      bool found = false;
      for (std::size_t k = 1; k < words.size() && !found; ++k) {
        const std::filesystem::path file = folder / words[k];
        std::error_code error;
        if (std::filesystem::is_regular_file(file, error)) {
          scan.material_files.push_back(file.string());
          found = true;
        }
      }
      if (!found) {
        std::string names;
        for (std::size_t k = 1; k < words.size(); ++k) {
          names += (k > 1 ? " '" : "'") + words[k] + "'";
        }
        scan.warnings.push_back(path + ":" + std::to_string(line) + ": material library " + names +
                                " not found, using default materials");
      }
    }
  }
  return scan;
}

// tinyobjloader's errors end in "line N.)"; the number when present, else 0.
int line_of(const std::string& message) {
  const std::size_t at = message.rfind("line ");
  return at == std::string::npos ? 0 : std::atoi(message.c_str() + at + 5);
}

glm::vec3 to_vec3(const tinyobj::real_t* v) {
  return glm::vec3(v[0], v[1], v[2]);
}

Material to_material(const tinyobj::material_t& m, const std::string& file) {
  Material out;
  out.ambient = to_vec3(m.ambient);
  out.diffuse = to_vec3(m.diffuse);
  out.specular = to_vec3(m.specular);
  out.emission = to_vec3(m.emission);
  out.shininess = m.shininess;
  out.preset.clear();
  const std::pair<const char*, glm::vec3> colours[] = {
      {"Ka", out.ambient}, {"Kd", out.diffuse}, {"Ks", out.specular}, {"Ke", out.emission}};
  for (const auto& [key, c] : colours) {
    for (int k = 0; k < 3; ++k) {
      if (!std::isfinite(c[k]) || c[k] < 0.0f) {
        throw InputError(file, "colour components must be finite and >= 0", 0, 0,
                         "material '" + m.name + "' " + key);
      }
    }
  }
  if (!std::isfinite(out.shininess) || out.shininess < 0.0f) {
    throw InputError(file, "must be finite and >= 0", 0, 0, "material '" + m.name + "' Ns");
  }
  return out;
}

// One part under construction: its vertices are the distinct (position, normal) index pairs of
// the file; normal index -1 means "compute from the faces".
struct PartBuilder {
  ObjPart part;
  std::map<std::pair<int, int>, unsigned> vertex_of;
  std::vector<std::pair<int, int>> source;  // file indices of each vertex

  unsigned vertex(int position, int normal, const tinyobj::attrib_t& attrib) {
    const auto [it, inserted] = vertex_of.try_emplace({position, normal}, 0u);
    if (inserted) {
      it->second = static_cast<unsigned>(part.mesh.positions.size());
      part.mesh.positions.push_back(to_vec3(&attrib.vertices[3 * position]));
      source.emplace_back(position, normal);
    }
    return it->second;
  }
};

// Normalised in double so tiny but non-zero file normals do not underflow.
glm::vec3 unit(const glm::vec3& v) {
  return glm::vec3(glm::normalize(glm::dvec3(v)));
}

// A file normal is used when it can be normalised; otherwise the vertex gets a computed one.
int usable_normal(int index, const tinyobj::attrib_t& attrib) {
  if (index < 0) return -1;
  const double len = glm::length(glm::dvec3(to_vec3(&attrib.normals[3 * index])));
  return len > 0.0 && std::isfinite(len) ? index : -1;
}

// Drops the vertices no triangle uses any more (after degenerate triangles were removed).
void remove_unused_vertices(PartBuilder& builder) {
  Mesh& mesh = builder.part.mesh;
  std::vector<unsigned> remap(mesh.positions.size(), ~0u);
  std::vector<glm::vec3> positions;
  std::vector<std::pair<int, int>> source;
  for (glm::uvec3& tri : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      unsigned& index = tri[k];
      if (remap[index] == ~0u) {
        remap[index] = static_cast<unsigned>(positions.size());
        positions.push_back(mesh.positions[index]);
        source.push_back(builder.source[index]);
      }
      index = remap[index];
    }
  }
  mesh.positions = std::move(positions);
  builder.source = std::move(source);
}

// Area-weighted normals per file position, summed over every kept triangle of every part so a
// smooth surface stays smooth across material boundaries. Where the sum cancels (two faces back
// to back) the first incident face's normal is used instead.
std::vector<glm::vec3> face_averaged_normals(const std::vector<PartBuilder>& parts,
                                             std::size_t position_count) {
  std::vector<glm::dvec3> sum(position_count, glm::dvec3(0.0));
  std::vector<glm::dvec3> first(position_count, glm::dvec3(0.0));
  std::vector<double> magnitude(position_count, 0.0);  // sum of |weighted|
  for (const PartBuilder& builder : parts) {
    const Mesh& mesh = builder.part.mesh;
    for (const glm::uvec3& tri : mesh.triangles) {
      const glm::dvec3 a(mesh.positions[tri.x]), b(mesh.positions[tri.y]), c(mesh.positions[tri.z]);
      const glm::dvec3 weighted = glm::cross(b - a, c - a);  // length = 2 * area
      for (int k = 0; k < 3; ++k) {
        const std::size_t p = static_cast<std::size_t>(builder.source[tri[k]].first);
        sum[p] += weighted;
        magnitude[p] += glm::length(weighted);
        if (first[p] == glm::dvec3(0.0)) first[p] = glm::normalize(weighted);
      }
    }
  }
  std::vector<glm::vec3> normals(position_count, glm::vec3(0.0f, 1.0f, 0.0f));
  for (std::size_t p = 0; p < position_count; ++p) {
    const double len = glm::length(sum[p]);
    const glm::dvec3 n = len > 1e-9 * magnitude[p] ? sum[p] / len : first[p];
    if (n != glm::dvec3(0.0)) normals[p] = glm::vec3(n);
  }
  return normals;
}

}  // namespace

ObjModel load_obj(const std::string& path, bool smooth) {
  std::error_code fs_error;
  if (std::filesystem::is_directory(path, fs_error)) throw InputError(path, "is a folder");
  std::ifstream file(path, std::ios::binary);
  if (!file) throw InputError(path, "cannot open file");
  std::ostringstream contents;
  contents << file.rdbuf();
  if (file.bad()) throw InputError(path, "cannot read file");
  const std::string text = contents.str();
  ObjScan scan = scan_obj(text, path);

  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> mtl;
  std::string warn, err;
  std::filesystem::path folder = std::filesystem::path(path).parent_path();
  if (folder.empty()) folder = ".";
  tinyobj::MaterialFileReader material_reader(folder.string() + "/");
  std::istringstream in(text);
  if (!tinyobj::LoadObj(&attrib, &shapes, &mtl, &warn, &err, &in, &material_reader, true, false)) {
    const std::string first_line = err.substr(0, err.find('\n'));
    throw InputError(path, first_line.empty() ? "cannot parse" : first_line, line_of(err));
  }
  if (attrib.vertices.empty()) throw InputError(path, "no vertices (not an OBJ file?)");

  ObjModel model;
  model.warnings = std::move(scan.warnings);
  const std::string& material_file =
      scan.material_files.size() == 1 ? scan.material_files[0] : path;
  for (const tinyobj::material_t& m : mtl) {
    model.material_names.push_back(m.name);
    model.materials.push_back(to_material(m, material_file));
  }
  for (const MaterialUse& use : scan.used_materials) {
    bool known = false;
    for (const std::string& name : model.material_names) known = known || name == use.name;
    if (!known) {
      model.warnings.push_back(path + ":" + std::to_string(use.line) + ": material '" + use.name +
                               "' is not defined; its faces get no material");
    }
  }

  // Parts in order of the first face that uses each material (-1: none or unknown).
  std::vector<PartBuilder> parts;
  std::map<int, std::size_t> part_of;
  std::size_t face_count = 0;
  for (const tinyobj::shape_t& shape : shapes) {
    std::size_t offset = 0;
    for (std::size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f) {
      const std::size_t corners = shape.mesh.num_face_vertices[f];
      int material = f < shape.mesh.material_ids.size() ? shape.mesh.material_ids[f] : -1;
      if (material < 0 || static_cast<std::size_t>(material) >= mtl.size()) material = -1;
      const auto [it, inserted] = part_of.try_emplace(material, parts.size());
      if (inserted) {
        parts.emplace_back();
        if (material >= 0) parts.back().part.material_name = mtl[material].name;
      }
      PartBuilder& builder = parts[it->second];
      std::vector<unsigned> face;
      for (std::size_t k = 0; k < corners; ++k) {
        const tinyobj::index_t& index = shape.mesh.indices[offset + k];
        const int normal = smooth ? usable_normal(index.normal_index, attrib) : -1;
        face.push_back(builder.vertex(index.vertex_index, normal, attrib));
      }
      for (std::size_t k = 1; k + 1 < corners; ++k) {  // already triangles; a fan otherwise
        builder.part.mesh.triangles.emplace_back(face[0], face[k], face[k + 1]);
      }
      offset += corners;
      ++face_count;
    }
  }
  if (face_count == 0) throw InputError(path, "no faces");

  std::size_t dropped = 0;
  for (PartBuilder& builder : parts) {
    dropped += drop_degenerate_triangles(builder.part.mesh);
    remove_unused_vertices(builder);
  }
  if (dropped > 0) {
    model.warnings.push_back(path + ": dropped " + std::to_string(dropped) +
                             " degenerate triangles");
  }

  if (smooth) {
    const std::vector<glm::vec3> averaged =
        face_averaged_normals(parts, attrib.vertices.size() / 3);
    for (PartBuilder& builder : parts) {
      for (const auto& [position, normal] : builder.source) {
        builder.part.mesh.normals.push_back(normal >= 0 ? unit(to_vec3(&attrib.normals[3 * normal]))
                                                        : averaged[position]);
      }
    }
  }
  for (PartBuilder& builder : parts) {
    if (!builder.part.mesh.triangles.empty()) model.parts.push_back(std::move(builder.part));
  }
  if (model.parts.empty()) throw InputError(path, "every face is degenerate");
  return model;
}

}  // namespace gloss
