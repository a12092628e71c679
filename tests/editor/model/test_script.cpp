// Script parsing (every command of docs/editor.md) and replay through the command layer; bad
// lines are errors that name the file and the line.
#include <gtest/gtest.h>

#include "base/error.h"
#include "editor/model/command_layer.h"
#include "editor/model/script.h"
#include "support/test_scene.h"

namespace gloss {
namespace {

template <class T>
const T& command_of(const ScriptLine& line) {
  return std::get<T>(std::get<Command>(line.action));
}

TEST(Script, ParsesEveryCommand) {
  const Script s = parse_script(
      "# a comment line\n"
      "preset 0 gold\n"
      "set 1 diffuse 0.5 0.25 0\n"
      "set 1 ambient 0.1   # one number is grey\n"
      "set 0 shininess 128\n"
      "model blinn-phong keep-size\n"
      "light 0 position 1 2 3\n"
      "camera orbit 30 -10\n"
      "\n"
      "undo\nredo\nwait\nwait 5\n"
      "screenshot out/a.png terms\n"
      "view term diffuse\nview ab\nexposure -1.5\nencoding srgb\nselect 1\n"
      "shadows off\nenergy on\nspp 8\nlight add\nlight remove 1\nstats\nsleep 0.5\n"
      "animate on\nquit\n",
      "s.txt");
  ASSERT_EQ(s.lines.size(), 26u);
  EXPECT_EQ(s.lines[0].line, 2);
  EXPECT_EQ(command_of<ApplyPreset>(s.lines[0]).name, "gold");
  EXPECT_EQ(command_of<SetMaterialColour>(s.lines[1]).value, glm::vec3(0.5f, 0.25f, 0.0f));
  EXPECT_EQ(command_of<SetMaterialColour>(s.lines[2]).value, glm::vec3(0.1f));
  EXPECT_EQ(command_of<SetShininess>(s.lines[3]).value, 128.0f);
  EXPECT_TRUE(command_of<SetModel>(s.lines[4]).keep_highlight_size);
  EXPECT_EQ(command_of<SetLightValue>(s.lines[5]).value, glm::vec3(1.0f, 2.0f, 3.0f));
  EXPECT_EQ(command_of<OrbitCamera>(s.lines[6]).pitch_deg, -10.0f);
  EXPECT_EQ(s.lines[6].line, 8);
  EXPECT_TRUE(std::holds_alternative<UndoAction>(s.lines[7].action));
  EXPECT_EQ(std::get<WaitAction>(s.lines[10].action).timeout_s, 5.0);
  EXPECT_EQ(std::get<ScreenshotAction>(s.lines[11].action).kind, ScreenshotKind::terms);
  EXPECT_EQ(std::get<ViewAction>(s.lines[12].action).term, TermView::diffuse);
  EXPECT_EQ(std::get<ViewAction>(s.lines[13].action).mode, ViewMode::ab);
  EXPECT_EQ(std::get<ExposureAction>(s.lines[14].action).stops, -1.5f);
  EXPECT_TRUE(std::get<EncodingAction>(s.lines[15].action).srgb);
  EXPECT_EQ(command_of<SetTargetSpp>(s.lines[19]).spp, 8);
  EXPECT_TRUE(std::holds_alternative<QuitAction>(s.lines.back().action));
}

TEST(Script, ScreenshotKindDefaultsToViewport) {
  const Script s = parse_script("screenshot shot.png\n", "s.txt");
  EXPECT_EQ(std::get<ScreenshotAction>(s.lines[0].action).kind, ScreenshotKind::viewport);
}

void expect_error_on_line(const std::string& text, int line, const std::string& words) {
  try {
    parse_script(text, "bad.txt");
    ADD_FAILURE() << "no error for: " << text;
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_EQ(e.file(), "bad.txt");
    EXPECT_NE(std::string(e.what()).find("bad.txt:" + std::to_string(line) + ":"),
              std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST(Script, BadLinesNameTheLine) {
  expect_error_on_line("wait\n\nfrobnicate 3\n", 3, "unknown command 'frobnicate'");
  expect_error_on_line("set 0 diffuse 1 0\n", 1, "missing colour");
  expect_error_on_line("set 0 gloss 5\n", 1, "unknown field 'gloss'");
  expect_error_on_line("set x shininess 5\n", 1, "object index");
  expect_error_on_line("model lambert\n", 1, "phong or blinn-phong");
  expect_error_on_line("quit\nquit now\n", 2, "unexpected 'now'");
  expect_error_on_line("screenshot a.png movie\n", 1, "viewport, terms or window");
  expect_error_on_line("camera orbit 10\n", 1, "missing");
  expect_error_on_line("light 0 colour 1 1 1\n", 1, "unknown light field");
}

TEST(Script, ReplayGoesThroughTheCommandLayer) {
  const Script s = parse_script("set 0 shininess 5\nset 0 shininess 6\nundo\n", "s.txt");
  CommandLayer layer(test::two_sphere_scene());
  for (const ScriptLine& line : s.lines) EXPECT_TRUE(run_document_line(line, layer, s.file));
  // Script lines are sealed one by one: undo takes back the second only.
  EXPECT_EQ(layer.scene().materials[0].shininess, 5.0f);
}

TEST(Script, AFailingCommandNamesItsLine) {
  const Script s = parse_script("wait\npreset 7 gold\n", "run.txt");
  CommandLayer layer(test::two_sphere_scene());
  EXPECT_FALSE(run_document_line(s.lines[0], layer, s.file));
  try {
    run_document_line(s.lines[1], layer, s.file);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 2);
    EXPECT_NE(std::string(e.what()).find("no object 7"), std::string::npos) << e.what();
  }
}

TEST(Script, UndoWithNothingToUndoIsAnError) {
  const Script s = parse_script("undo\n", "s.txt");
  CommandLayer layer(test::two_sphere_scene());
  EXPECT_THROW(run_document_line(s.lines[0], layer, s.file), InputError);
}

}  // namespace
}  // namespace gloss
