// Export GLSL's text (editor/model/export/glsl_export.h) and its script verb `export glsl PATH
// [OBJECT]`. Whether the shader computes the contract is tested through GL in tests/editor/gl.
#include "editor/model/export/glsl_export.h"

#include <cstdio>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "base/atomic_file.h"
#include "base/error.h"
#include "editor/model/script/script.h"
#include "editor/model/script/script_runner.h"
#include "support/quiet_script_host.h"
#include "support/scratch_folder.h"
#include "support/test_scene.h"

namespace gloss {
namespace {

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(GlslExport, FillsTheMaterialAndLightsWithTheirSources) {
  Scene scene = test::two_sphere_scene();
  scene.render.model = ShadingModel::blinn_phong;
  scene.render.energy_normalize = true;
  scene.lights[1].attenuation = {0.5f, 0.25f, 0.125f};
  const std::string s = export_glsl(scene, 1);  // "blue"
  EXPECT_EQ(s.rfind("#version 330 core\n", 0), 0u) << "the version line comes first";
  EXPECT_TRUE(contains(s,
                       "const vec3 gloss_kd = vec3(0.100000001, 0.100000001, 0.699999988);  "
                       "// materials[1] \"blue\".diffuse\n"))
      << s;
  EXPECT_TRUE(contains(s, "const float gloss_alpha = 10.0;  // materials[1] \"blue\".shininess"));
  EXPECT_TRUE(contains(s, "const vec3 gloss_ks = vec3(1.0, 1.0, 1.0);"));
  EXPECT_TRUE(contains(s,
                       "const vec3 gloss_scene_ambient = vec3(0.200000003, 0.200000003, "
                       "0.200000003);  // scene ambient"));
  EXPECT_TRUE(contains(s, "const int gloss_model = 1;  // render.model \"blinn-phong\""));
  EXPECT_TRUE(contains(s, "const bool gloss_energy_normalize = true;"));
  EXPECT_TRUE(contains(s, "#define GLOSS_LIGHT_COUNT 2\n"));
  EXPECT_TRUE(contains(s, "    vec3(4.0, 4.0, 4.0),  // lights[0].position\n"));
  EXPECT_TRUE(contains(s, "    vec3(0.5, 0.25, 0.125)   // lights[1].attenuation (c0, c1, c2)\n"));
  EXPECT_TRUE(contains(s, "shadows on (render.shadows)"));
  EXPECT_TRUE(contains(s, kPhongContractGlsl)) << "the contract file's code, whole";
  EXPECT_TRUE(
      contains(s, "in vec3 gloss_position;\nin vec3 gloss_normal;\nuniform vec3 gloss_eye;"));
}

TEST(GlslExport, NoLightsLeavesNoArrays) {
  Scene scene = test::two_sphere_scene();
  scene.lights.clear();
  scene.render.shadows = false;
  const std::string s = export_glsl(scene, 0);
  EXPECT_TRUE(contains(s, "#define GLOSS_LIGHT_COUNT 0\n"));
  EXPECT_FALSE(contains(s, "const vec3 gloss_light_position[")) << "GLSL has no arrays of size 0";
  EXPECT_TRUE(contains(s, "shadows off"));
}

TEST(GlslExport, NamesFromFilesCannotEndAComment) {
  Scene scene = test::two_sphere_scene();
  scene.material_names[0] = "red\nvoid main() {}";
  scene.path = "a\rb.json";
  const std::string s = export_glsl(scene, 0);
  EXPECT_TRUE(contains(s, "materials[0] \"red\\x0Avoid main() {}\""));
  EXPECT_TRUE(contains(s, "from a\\x0Db.json."));
  EXPECT_FALSE(contains(s, "\nvoid main() {}"));
}

TEST(GlslExport, RefusesAMissingMaterial) {
  const Scene scene = test::two_sphere_scene();
  EXPECT_THROW(export_glsl(scene, 2), std::out_of_range);
  EXPECT_THROW(export_glsl(scene, -1), std::out_of_range);
}

using Host = test::QuietScriptHost;

LineResult run(const std::string& text, Host& host) {
  return test::run_quietly(text, host);
}

TEST(GlslExportScript, Parses) {
  const Script s = parse_script("export glsl a.frag\nexport glsl b.frag 1\n", "s.txt");
  ASSERT_EQ(s.lines.size(), 2u);
  EXPECT_EQ(std::get<ExportGlslAction>(s.lines[0].action).path, "a.frag");
  EXPECT_EQ(std::get<ExportGlslAction>(s.lines[0].action).object, -1);
  EXPECT_EQ(std::get<ExportGlslAction>(s.lines[1].action).object, 1);
  EXPECT_THROW(parse_script("export png a.png\n", "s.txt"), InputError);
  EXPECT_THROW(parse_script("export glsl\n", "s.txt"), InputError);
  EXPECT_THROW(parse_script("export glsl a.frag x\n", "s.txt"), InputError);
}

TEST(GlslExportScript, WritesTheSelectedOrNamedObjectsMaterial) {
  ScratchFolder folder;
  Host host(test::two_sphere_scene());
  EXPECT_EQ(run("select 1\nexport glsl " + folder.file("selected.frag") + "\nexport glsl " +
                    folder.file("named.frag") + " 0\n",
                host)
                .next,
            LineResult::Next::go_on);
  EXPECT_TRUE(contains(read_text_file(folder.file("selected.frag")), "materials[1] \"blue\""));
  EXPECT_TRUE(contains(read_text_file(folder.file("named.frag")), "materials[0] \"red\""));
}

TEST(GlslExportScript, FailuresStopWithTheirStatusAndLeaveNoFile) {
  ScratchFolder folder;
  Host host(test::two_sphere_scene());
  const LineResult bad_object = run("export glsl " + folder.file("x.frag") + " 7\n", host);
  EXPECT_EQ(bad_object.next, LineResult::Next::stop);
  EXPECT_EQ(bad_object.status, 2);
  const LineResult unwritable =
      run("export glsl " + folder.file("missing-folder/x.frag") + "\n", host);
  EXPECT_EQ(unwritable.next, LineResult::Next::stop);
  EXPECT_EQ(unwritable.status, 1);
  EXPECT_TRUE(folder.entries().empty());
}

}  // namespace
}  // namespace gloss
