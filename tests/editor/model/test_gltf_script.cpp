// The script line `export gltf PATH` (editor/model/export/gltf_file.h): parsed, written by the
// headless host as the CLI writes it (read back exactly by gloss), failures stop with status 1
// and leave no file; the summary names each material's fit and its error.
#include <gtest/gtest.h>

#include "base/error.h"
#include "editor/model/export/gltf_file.h"
#include "editor/model/script/script.h"
#include "editor/model/script/script_runner.h"
#include "io/model/model_loader.h"
#include "support/quiet_script_host.h"
#include "support/scratch_folder.h"
#include "support/test_scene.h"

namespace gloss {
namespace {

LineResult run(const std::string& text, test::QuietScriptHost& host) {
  return test::run_quietly(text, host);
}

TEST(GltfScript, Parses) {
  const Script s = parse_script("export gltf a.glb\n", "s.txt");
  ASSERT_EQ(s.lines.size(), 1u);
  EXPECT_EQ(std::get<ExportGltfAction>(s.lines[0].action).path, "a.glb");
  EXPECT_THROW(parse_script("export gltf\n", "s.txt"), InputError);
  EXPECT_THROW(parse_script("export gltf a.glb extra\n", "s.txt"), InputError);
}

TEST(GltfScript, WritesTheSceneThatReadsBackExactly) {
  ScratchFolder folder;
  test::QuietScriptHost host(test::two_sphere_scene());
  const std::string path = folder.file("scene.glb");
  EXPECT_EQ(run("export gltf " + path + "\n", host).next, LineResult::Next::go_on);
  const Model model = load_model(path);
  const Scene& scene = host.layer().scene();
  ASSERT_EQ(model.materials.size(), scene.materials.size());
  EXPECT_EQ(model.exact_materials, static_cast<int>(scene.materials.size()));
}

TEST(GltfScript, FailuresStopAndLeaveNoFile) {
  ScratchFolder folder;
  test::QuietScriptHost host(test::two_sphere_scene());
  const LineResult r = run("export gltf " + folder.file("missing/scene.glb") + "\n", host);
  EXPECT_EQ(r.next, LineResult::Next::stop);
  EXPECT_EQ(r.status, 1);
  EXPECT_TRUE(folder.entries().empty());
}

TEST(GltfScript, SummaryNamesEachMaterialsFit) {
  ScratchFolder folder;
  const Scene scene = test::two_sphere_scene();
  const std::string summary = write_gltf_file(scene, folder.file("s.gltf"), false);
  EXPECT_EQ(summary.rfind("exported " + folder.file("s.gltf") + ":", 0), 0u) << summary;
  // Each material's fit with its residual in both metrics (l2 relative, then L*).
  for (const std::string& name : scene.material_names) {
    const std::size_t at = summary.find(" " + name + " roughness ");
    ASSERT_NE(at, std::string::npos) << summary;
    const std::size_t error = summary.find(" error ", at);
    ASSERT_NE(error, std::string::npos) << summary;
    EXPECT_NE(summary.find(" % (L* ", error), std::string::npos) << summary;
  }
}

}  // namespace
}  // namespace gloss
