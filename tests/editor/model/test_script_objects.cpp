// The object and material lines of scripts (docs/editor.md, "Scripted mode"), spelled exactly as
// outside scripts rely on them: every spelling parses, bad ones name the line, names resolve when
// the line runs (indices shift down after a delete), quoted words hold spaces.
#include <gtest/gtest.h>

#include "base/error.h"
#include "editor/model/script/script.h"
#include "editor/model/script/script_runner.h"
#include "support/quiet_script_host.h"
#include "support/script_checks.h"
#include "support/test_scene.h"

namespace gloss {
namespace {

const ObjectLineAction& object_line(const ScriptLine& line) {
  return std::get<ObjectLineAction>(line.action);
}

TEST(ScriptObjects, ParsesEverySpelling) {
  using Verb = ObjectLineAction::Verb;
  const Script s = parse_script(
      "object add sphere\n"
      "object add teapot\n"
      "object add model \"/models/my bull.obj\"   # a path with a space\n"
      "object 0 move 1 2 3\n"
      "object \"gold ball\" rotate 0 90 0\n"
      "object 2 scale 2\n"
      "object 2 scale 1 2 3\n"
      "object left delete\nobject left duplicate\nobject left hide\nobject left show\n"
      "object left solo\n"
      "object 1 name \"polished \\\"brass\\\" ball\"\n"
      "material rename red \"polished brass\"\n"
      "assign left blue\n"
      "object \"12\" hide\n"
      "object 0 pivot 0 0 0\n",
      "s.txt");
  ASSERT_EQ(s.lines.size(), 17u);
  EXPECT_EQ(object_line(s.lines[0]).verb, Verb::add);
  EXPECT_EQ(object_line(s.lines[0]).type, ObjectType::sphere);
  EXPECT_EQ(object_line(s.lines[1]).type, ObjectType::teapot);
  EXPECT_EQ(object_line(s.lines[2]).verb, Verb::add_model);
  EXPECT_EQ(object_line(s.lines[2]).text, "/models/my bull.obj");
  EXPECT_EQ(s.lines[2].text, "object add model \"/models/my bull.obj\"   ");
  const ObjectLineAction& move = object_line(s.lines[3]);
  EXPECT_EQ(move.object.index, 0);
  EXPECT_EQ(move.field.part, FieldPart::transform);
  EXPECT_EQ(move.field.key, "translate");
  EXPECT_EQ(move.field.value.v, glm::vec3(1, 2, 3));
  EXPECT_EQ(object_line(s.lines[4]).object.name, "gold ball");
  EXPECT_EQ(object_line(s.lines[4]).field.key, "rotate");
  EXPECT_EQ(object_line(s.lines[5]).field.value.v, glm::vec3(2, 2, 2));  // one number: uniform
  EXPECT_EQ(object_line(s.lines[6]).field.value.v, glm::vec3(1, 2, 3));
  EXPECT_EQ(object_line(s.lines[7]).verb, Verb::remove);
  EXPECT_EQ(object_line(s.lines[7]).object.name, "left");
  EXPECT_EQ(object_line(s.lines[8]).verb, Verb::duplicate);
  EXPECT_EQ(object_line(s.lines[9]).verb, Verb::hide);
  EXPECT_EQ(object_line(s.lines[10]).verb, Verb::show);
  EXPECT_EQ(object_line(s.lines[11]).verb, Verb::solo);
  EXPECT_EQ(object_line(s.lines[12]).text, "polished \"brass\" ball");
  EXPECT_EQ(object_line(s.lines[13]).verb, Verb::rename_material);
  EXPECT_EQ(object_line(s.lines[13]).text, "red");
  EXPECT_EQ(object_line(s.lines[13]).text2, "polished brass");
  EXPECT_EQ(object_line(s.lines[14]).verb, Verb::assign);
  EXPECT_EQ(object_line(s.lines[14]).text, "blue");
  EXPECT_EQ(object_line(s.lines[15]).object.index, -1);  // quoted: a name, not an index
  EXPECT_EQ(object_line(s.lines[15]).object.name, "12");
  EXPECT_EQ(object_line(s.lines[16]).field.key, "pivot");
}

using test::expect_script_error;

TEST(ScriptObjects, BadLinesNameTheLine) {
  expect_script_error("wait\nobject 0 spin 1 2 3\n", 2, "object OBJECT takes move, rotate");
  expect_script_error("object add cone\n", 1, "object add takes sphere, quad, box, teapot");
  expect_script_error("object 0 move 1 2\n", 1, "missing translate");
  expect_script_error("object 0 scale 1 2\n", 1, "missing scale");
  expect_script_error("object 0 hide now\n", 1, "unexpected 'now'");
  expect_script_error("material delete red\n", 1, "material takes 'rename OLD NEW'");
  expect_script_error("assign 0\n", 1, "missing material name");
  expect_script_error("\n\nobject 0 name \"gold\n", 3, "a quote is not closed");
  expect_script_error("object\n", 1, "missing object");
}

int run_all(const std::string& text, test::QuietScriptHost& host, std::string& errors) {
  return test::run_script_text(text, "run.txt", host, errors);
}

TEST(ScriptObjects, IndicesShiftDownAfterADeleteAndNamesFollowTheirObject) {
  test::QuietScriptHost host(test::two_sphere_scene());  // 0 "left", 1 "right"
  std::string errors;
  ASSERT_EQ(run_all("object 0 delete\n"
                    "object 0 name \"was right\"\n"  // the old object 1
                    "object \"was right\" move 0 1 0\n"
                    "material rename red \"polished brass\"\n"
                    "assign 0 \"polished brass\"\n",
                    host, errors),
            0)
      << errors;
  const Scene& scene = host.layer().scene();
  ASSERT_EQ(scene.objects.size(), 1u);
  EXPECT_EQ(scene.objects[0].name, "was right");
  EXPECT_EQ(scene.objects[0].center, glm::vec3(1.2f, 1.0f, 0.0f));
  EXPECT_EQ(scene.material_names[scene.objects[0].material], "polished brass");
  EXPECT_EQ(host.layer().undo_count(), 5u);  // one step per line
}

TEST(ScriptObjects, SelectTakesANameToo) {
  test::QuietScriptHost host(test::two_sphere_scene());
  std::string errors;
  ASSERT_EQ(run_all("select right\n", host, errors), 0) << errors;
  EXPECT_EQ(host.selected_object(), 1);
  EXPECT_EQ(run_all("select \"lefty\"\n", host, errors), 2);
  EXPECT_NE(errors.find("run.txt:1: no object called 'lefty'"), std::string::npos) << errors;
}

// docs/editor.md: "OBJECT is an index or a name" for `set` and `preset` too (they took an index
// only: "expected an index for object index, got 'right'").
TEST(ScriptObjects, SetAndPresetTakeANameToo) {
  test::QuietScriptHost host(test::two_sphere_scene());  // 0 "left", 1 "right"
  std::string errors;
  ASSERT_EQ(run_all("set right shininess 5\n"
                    "preset left ruby\n"
                    "set \"right\" diffuse 0.25\n",
                    host, errors),
            0)
      << errors;
  const Scene& scene = host.layer().scene();
  EXPECT_EQ(scene.materials[scene.objects[1].material].shininess, 5.0f);
  EXPECT_EQ(scene.materials[scene.objects[1].material].diffuse, glm::vec3(0.25f));
  EXPECT_EQ(scene.materials[scene.objects[0].material].preset, "ruby");
  EXPECT_EQ(host.layer().undo_count(), 3u);
  EXPECT_EQ(run_all("set rigth shininess 7\n", host, errors), 2);
  EXPECT_NE(errors.find("run.txt:1: no object called 'rigth' (did you mean 'right'"),
            std::string::npos)
      << errors;
  // A field is still checked when the script is read, before any line runs.
  test::expect_script_error("set right gloss 5\n", 1, "unknown material field 'gloss'");
}

TEST(ScriptObjects, AddedObjectsAreSelected) {
  test::QuietScriptHost host(test::two_sphere_scene());
  std::string errors;
  ASSERT_EQ(run_all("object add box\n", host, errors), 0) << errors;
  EXPECT_EQ(host.layer().scene().objects.size(), 3u);
  EXPECT_EQ(host.selected_object(), 2);
  EXPECT_EQ(host.layer().scene().objects[2].name, "box");
}

TEST(ScriptObjects, AnUnknownNameStopsTheScriptNamingTheLine) {
  test::QuietScriptHost host(test::two_sphere_scene());
  std::string errors;
  EXPECT_EQ(run_all("object left hide\nobject lefty show\nobject right hide\n", host, errors), 2);
  EXPECT_NE(errors.find("error: run.txt:2: no object called 'lefty' (did you mean 'left'"),
            std::string::npos)
      << errors;
  EXPECT_TRUE(host.layer().scene().objects[0].hidden);
  EXPECT_FALSE(host.layer().scene().objects[1].hidden);  // the script stopped before it
  EXPECT_EQ(run_all("object 5 hide\n", host, errors), 2);
  EXPECT_NE(errors.find("run.txt:1: no object 5 (the scene has 2)"), std::string::npos) << errors;
  EXPECT_EQ(run_all("assign 0 gren\n", host, errors), 2);
  EXPECT_NE(errors.find("no material called 'gren'"), std::string::npos) << errors;
  EXPECT_EQ(run_all("object add model /no/such.obj\n", host, errors), 2);
  EXPECT_NE(errors.find("run.txt:1: /no/such.obj"), std::string::npos) << errors;
}

}  // namespace
}  // namespace gloss
