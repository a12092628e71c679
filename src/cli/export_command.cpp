// gloss-cli export-gltf SCENE OUT.gltf|OUT.glb [--threejs FILE] [--json FILE] [--segments N]
// gloss-cli export-threejs SCENE OUT.json [--json FILE]
// The scene as glTF 2.0 (materials fitted as metallic-roughness, exact Phong in extras), its
// materials as three.js JSON, and each conversion's error printed (docs/export.md).
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "base/atomic_file.h"
#include "base/error.h"
#include "cli/commands.h"
#include "cli/scene_messages.h"
#include "export/gltf_export.h"
#include "export/material_conversion.h"
#include "export/threejs_export.h"
#include "io/scene/scene_loader.h"

namespace gloss {

namespace {

struct ExportArgs {
  std::string scene, out, threejs, json;
  int segments = 64;
};

void report(const std::vector<MaterialConversion>& conversions, const ExportArgs& args) {
  for (const std::string& line : conversion_lines(conversions)) std::cout << line << "\n";
  if (!args.json.empty()) {
    write_text_atomically(args.json, conversion_json(conversions));
    std::cout << "wrote " << args.json << "\n";
  }
}

Scene load(const ExportArgs& args) {
  std::vector<std::string> warnings, notes;
  Scene scene = load_scene(args.scene, &warnings, &notes);
  print_scene_messages(notes, warnings);
  return scene;
}

void write_threejs(const Scene& scene, const std::vector<MaterialConversion>& conversions,
                   const std::string& path) {
  const ThreejsExport out = threejs_export(scene, conversions, path);
  for (const std::string& notice : out.notices) std::cout << "note: " << notice << "\n";
  write_text_atomically(path, out.json);
  std::cout << "wrote " << path << "\n";
}

void run_export_gltf(const ExportArgs& args) {
  if (!is_gltf_path(args.out)) {
    throw InputError(args.out, "a glTF export is written to FILE.gltf or FILE.glb");
  }
  if (args.segments < 8 || args.segments > 1024) {
    throw InputError("export-gltf", "must be from 8 to 1024", 0, 0, "--segments");
  }
  const Scene scene = load(args);
  const std::vector<MaterialConversion> conversions = convert_materials(scene);
  GltfExportOptions options;
  options.sphere_segments = args.segments;
  const GltfExportResult result = export_gltf(scene, conversions, args.out, options);
  for (const std::string& notice : result.notices) std::cout << "note: " << notice << "\n";
  report(conversions, args);
  if (!args.threejs.empty()) write_threejs(scene, conversions, args.threejs);
  std::cout << "wrote " << args.out << " (" << result.bytes << " bytes)\n";
}

void run_export_threejs(const ExportArgs& args) {
  const Scene scene = load(args);
  const std::vector<MaterialConversion> conversions = convert_materials(scene);
  report(conversions, args);
  write_threejs(scene, conversions, args.out);
}

}  // namespace

void add_export_commands(CLI::App& app) {
  auto args = std::make_shared<ExportArgs>();
  CLI::App* gltf = app.add_subcommand(
      "export-gltf",
      "The scene as glTF 2.0: geometry, camera, lights, materials fitted as metallic-roughness "
      "(exact Phong in extras), with each conversion's error");
  gltf->add_option("scene", args->scene, "Scene file")->required();
  gltf->add_option("out", args->out, "OUT.gltf (with OUT.bin beside it) or OUT.glb")->required();
  gltf->add_option("--threejs", args->threejs, "Also write the materials as three.js JSON");
  gltf->add_option("--json", args->json, "Also write the conversions and their errors as JSON");
  gltf->add_option("--segments", args->segments,
                   "Triangles around a sphere's equator, 8..1024 (default 64)");
  gltf->callback([args] { run_export_gltf(*args); });

  auto targs = std::make_shared<ExportArgs>();
  CLI::App* three = app.add_subcommand(
      "export-threejs",
      "The scene's materials as three.js MeshPhongMaterial (fitted to three.js's Phong) and "
      "MeshStandardMaterial JSON, with each conversion's error");
  three->add_option("scene", targs->scene, "Scene file")->required();
  three->add_option("out", targs->out, "OUT.json")->required();
  three->add_option("--json", targs->json, "Also write the conversions and their errors as JSON");
  three->callback([targs] { run_export_threejs(*targs); });
}

}  // namespace gloss
