// Script parsing (every command of docs/editor.md) and replay through the command layer; bad
// lines are errors that name the file and the line.
#include <filesystem>

#include <gtest/gtest.h>

#include "base/assets.h"
#include "base/error.h"
#include "editor/model/document/command_layer.h"
#include "editor/model/script/script.h"
#include "editor/model/script/script_runner.h"
#include "support/script_checks.h"
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
  EXPECT_EQ(command_of<SetField>(s.lines[1]).part, FieldPart::material);
  EXPECT_EQ(command_of<SetField>(s.lines[1]).index, 1);
  EXPECT_EQ(command_of<SetField>(s.lines[1]).key, "diffuse");
  EXPECT_EQ(command_of<SetField>(s.lines[1]).value.v, glm::vec3(0.5f, 0.25f, 0.0f));
  EXPECT_EQ(command_of<SetField>(s.lines[2]).value.v, glm::vec3(0.1f));
  EXPECT_EQ(command_of<SetField>(s.lines[3]).key, "shininess");
  EXPECT_EQ(command_of<SetField>(s.lines[3]).value.x, 128.0);
  EXPECT_TRUE(command_of<SetModel>(s.lines[4]).keep_highlight_size);
  EXPECT_EQ(command_of<SetField>(s.lines[5]).part, FieldPart::light);
  EXPECT_EQ(command_of<SetField>(s.lines[5]).key, "position");
  EXPECT_EQ(command_of<SetField>(s.lines[5]).value.v, glm::vec3(1.0f, 2.0f, 3.0f));
  EXPECT_EQ(command_of<OrbitCamera>(s.lines[6]).pitch_deg, -10.0f);
  EXPECT_EQ(s.lines[6].line, 8);
  EXPECT_TRUE(std::holds_alternative<UndoAction>(s.lines[7].action));
  EXPECT_EQ(std::get<WaitAction>(s.lines[10].action).timeout_s, 5.0);
  EXPECT_EQ(std::get<ScreenshotAction>(s.lines[11].action).kind, ScreenshotKind::terms);
  EXPECT_EQ(std::get<ViewAction>(s.lines[12].action).term, TermView::diffuse);
  EXPECT_EQ(std::get<ViewAction>(s.lines[13].action).mode, ViewMode::ab);
  EXPECT_EQ(command_of<SetField>(s.lines[14]).part, FieldPart::render);  // the document's now
  EXPECT_EQ(command_of<SetField>(s.lines[14]).key, "exposure");
  EXPECT_EQ(command_of<SetField>(s.lines[14]).value.x, -1.5);
  EXPECT_EQ(command_of<SetField>(s.lines[15]).part, FieldPart::render);
  EXPECT_EQ(command_of<SetField>(s.lines[15]).key, "srgb");
  EXPECT_EQ(command_of<SetField>(s.lines[15]).value.x, 1.0);
  EXPECT_EQ(command_of<SetField>(s.lines[17]).key, "shadows");
  EXPECT_EQ(command_of<SetField>(s.lines[17]).value.x, 0.0);
  EXPECT_EQ(command_of<SetField>(s.lines[18]).key, "energy_normalize");
  EXPECT_EQ(command_of<SetField>(s.lines[19]).key, "spp");
  EXPECT_EQ(command_of<SetField>(s.lines[19]).value.x, 8.0);
  EXPECT_TRUE(std::holds_alternative<QuitAction>(s.lines.back().action));
}

TEST(Script, ScreenshotKindDefaultsToViewport) {
  const Script s = parse_script("screenshot shot.png\n", "s.txt");
  EXPECT_EQ(std::get<ScreenshotAction>(s.lines[0].action).kind, ScreenshotKind::viewport);
}

void expect_error_on_line(const std::string& text, int line, const std::string& words) {
  test::expect_script_error(text, line, words);
}

TEST(Script, BadLinesNameTheLine) {
  expect_error_on_line("wait\n\nfrobnicate 3\n", 3, "unknown command 'frobnicate'");
  expect_error_on_line("set 0 diffuse 1 0\n", 1, "missing colour");
  expect_error_on_line("set 0 gloss 5\n", 1, "unknown material field 'gloss'");
  expect_error_on_line("set\n", 1, "missing object (an index or a name)");
  expect_error_on_line("model lambert\n", 1, "phong or blinn-phong");
  expect_error_on_line("wait -1\n", 1, "the timeout must be a finite number of seconds > 0");
  expect_error_on_line("wait inf\n", 1, "the timeout must be a finite number of seconds > 0");
  expect_error_on_line("render spp 0x10\n", 1, "expected a whole number");
  expect_error_on_line("set 0 diffuse 0x10\n", 1, "expected a number for");
  expect_error_on_line("set 0 shininess 0x1p4\n", 1, "expected a number for");
  expect_error_on_line("quit\nquit now\n", 2, "unexpected 'now'");
  expect_error_on_line("screenshot a.png movie\n", 1, "viewport, terms, window, shown or exr");
  expect_error_on_line("screenshot a.jpg shown\n", 1, ".png or .pfm");
  expect_error_on_line("camera orbit 10\n", 1, "missing");
  expect_error_on_line("light 0 colour 1 1 1\n", 1, "unknown light field");
}

// A host that records what the dispatcher hands it (script_runner.h).
class RecordingHost : public ScriptHost {
 public:
  explicit RecordingHost(Scene scene) : m_layer(std::move(scene)) {}
  CommandLayer& layer() override { return m_layer; }
  ViewSettings& view() override { return m_view; }
  void select(int object) override { selected = object; }
  LineResult wait(const WaitAction&, const std::string&) override {
    ++waits;
    return LineResult::hold();
  }
  LineResult screenshot(const ScreenshotAction&, const std::string&) override {
    return LineResult::go_on();
  }
  LineResult stats() override { return LineResult::go_on(); }
  LineResult sleep(const SleepAction&) override { return LineResult::go_on(); }
  LineResult quality(const QualityAction&, const std::string&) override {
    return LineResult::go_on();
  }
  LineResult memory() override {
    ++memory_reports;
    return LineResult::go_on();
  }

  int waits = 0;
  int memory_reports = 0;
  int selected = -1;

 private:
  CommandLayer m_layer;
  ViewSettings m_view;
};

// Runs every line of text on host; returns what the last line left to do and its stderr.
LineResult run_all(const std::string& text, RecordingHost& host, std::string& errors);

TEST(Script, MemoryIsHandedToTheHostAndTakesNoArgument) {
  RecordingHost host(test::two_sphere_scene());
  std::string errors;
  EXPECT_EQ(run_all("memory\nmemory\n", host, errors).next, LineResult::Next::go_on);
  EXPECT_EQ(host.memory_reports, 2);
  EXPECT_THROW(parse_script("memory now\n", "m.txt"), InputError);
}

// Runs every line of text on host; returns what the last line left to do and its stderr.
LineResult run_all(const std::string& text, RecordingHost& host, std::string& errors) {
  const Script s = parse_script(text, "run.txt");
  testing::internal::CaptureStderr();
  LineResult result;
  for (const ScriptLine& line : s.lines) {
    result = run_script_line(s, line, host);
    if (result.next == LineResult::Next::stop) break;
  }
  errors = testing::internal::GetCapturedStderr();
  return result;
}

TEST(Script, ReplayGoesThroughTheCommandLayer) {
  RecordingHost host(test::two_sphere_scene());
  std::string errors;
  const LineResult r = run_all("set 0 shininess 5\nset 0 shininess 6\nundo\n", host, errors);
  EXPECT_EQ(r.next, LineResult::Next::go_on);
  // Script lines are sealed one by one: undo takes back the second only.
  EXPECT_EQ(host.layer().scene().materials[0].shininess, 5.0f);
  EXPECT_EQ(errors, "");
}

// A script never saves over a scene gloss ships: exit 2, nothing written.
TEST(Script, SavingOverAShippedSceneIsRefused) {
  RecordingHost host(test::two_sphere_scene());
  std::string errors;
  const std::string target = asset_path("scenes/zz-save-refused-test.json");
  const LineResult r = run_all("save " + target + "\n", host, errors);
  EXPECT_EQ(r.next, LineResult::Next::stop);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(errors.find("run.txt:1: " + target + " is a scene gloss ships"), std::string::npos)
      << errors;
  EXPECT_FALSE(std::filesystem::exists(target));
  std::filesystem::remove(target);  // should the refusal ever fail, no stray file stays
}

TEST(Script, ViewLinesAndWaitsGoToTheHost) {
  RecordingHost host(test::two_sphere_scene());
  std::string errors;
  const LineResult r = run_all("view term diffuse\nselect 1\nanimate on\nwait\n", host, errors);
  EXPECT_EQ(r.next, LineResult::Next::hold);
  EXPECT_EQ(host.view().mode, ViewMode::single);
  EXPECT_EQ(host.view().single, TermView::diffuse);
  EXPECT_TRUE(host.view().orbit_light);
  EXPECT_EQ(host.selected, 1);
  EXPECT_EQ(host.waits, 1);
}

TEST(Script, AFailingCommandNamesItsLine) {
  RecordingHost host(test::two_sphere_scene());
  std::string errors;
  const LineResult r = run_all("exposure 1\npreset 7 gold\nquit\n", host, errors);
  EXPECT_EQ(r.next, LineResult::Next::stop);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(errors.rfind("error: run.txt:2: ", 0), 0u) << errors;
  EXPECT_NE(errors.find("no object 7"), std::string::npos) << errors;
}

TEST(Script, AnInvalidValueIsRefusedByTheOneValidator) {
  RecordingHost host(test::two_sphere_scene());
  std::string errors;
  const LineResult r = run_all("light 0 attenuation 0 0 0\n", host, errors);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(errors.find("lights[0].attenuation: coefficients"), std::string::npos) << errors;
  EXPECT_EQ(host.layer().scene().lights[0].attenuation, glm::vec3(1.0f, 0.0f, 0.0f));
}

// Found by fuzz/fuzz_script: `render height 6811e395` parses as a whole number (inf is whole) and
// the setter converted inf to int before validation saw it (undefined behaviour; UBSan: "inf is
// outside the range of representable values of type 'int'"). The value is now refused by the
// field's own rule first, and the document is unchanged.
TEST(Script, AnOutOfRangeWholeNumberIsRefusedBeforeItIsConverted) {
  for (const char* value : {"6811e395", "-1e300", "3e9", "16385"}) {
    RecordingHost host(test::two_sphere_scene());
    const int height = host.layer().scene().render.height;
    std::string errors;
    const LineResult r = run_all(std::string("render height ") + value + "\n", host, errors);
    EXPECT_EQ(r.status, 2) << value;
    EXPECT_NE(errors.find("render height: must be a whole number from 1 to 16384"),
              std::string::npos)
        << errors;
    EXPECT_EQ(host.layer().scene().render.height, height);
    EXPECT_EQ(host.layer().undo_count(), 0u);
  }
}

TEST(Script, UndoWithNothingToUndoIsAnError) {
  RecordingHost host(test::two_sphere_scene());
  std::string errors;
  EXPECT_EQ(run_all("undo\n", host, errors).status, 2);
  EXPECT_NE(errors.find("nothing to undo"), std::string::npos) << errors;
}

TEST(Script, ParsesTheRendererAndRasterKnobs) {
  const Script s = parse_script(
      "renderer gl\nrenderer cpu\nrenderer auto\nshading vertex\nshading pixel\n"
      "shadow-map 16\nshadow-map 4096\nshadow-bias 0\nshadow-bias 2.5\n"
      "view ab cpu-gl\nview ab pixel-vertex\n",
      "r.txt");
  ASSERT_EQ(s.lines.size(), 11u);
  EXPECT_EQ(std::get<RendererAction>(s.lines[0].action).choice, RendererChoice::gl);
  EXPECT_EQ(std::get<RendererAction>(s.lines[1].action).choice, RendererChoice::cpu);
  EXPECT_EQ(std::get<RendererAction>(s.lines[2].action).choice, RendererChoice::automatic);
  EXPECT_EQ(std::get<ShadingAction>(s.lines[3].action).frequency, ShadingFrequency::vertex);
  EXPECT_EQ(std::get<ShadingAction>(s.lines[4].action).frequency, ShadingFrequency::pixel);
  EXPECT_EQ(std::get<ShadowMapAction>(s.lines[5].action).size, 16);
  EXPECT_EQ(std::get<ShadowMapAction>(s.lines[6].action).size, 4096);
  EXPECT_EQ(std::get<ShadowBiasAction>(s.lines[7].action).texels, 0.0f);
  EXPECT_EQ(std::get<ShadowBiasAction>(s.lines[8].action).texels, 2.5f);
  EXPECT_EQ(std::get<ViewAction>(s.lines[9].action).mode, ViewMode::ab);
  EXPECT_EQ(std::get<ViewAction>(s.lines[9].action).ab_source, AbSource::cpu_gl);
  EXPECT_EQ(std::get<ViewAction>(s.lines[10].action).ab_source, AbSource::pixel_vertex);
}

TEST(Script, BadRendererAndRasterValuesNameTheLine) {
  expect_error_on_line("renderer\n", 1, "missing renderer");
  expect_error_on_line("wait\nrenderer vulkan\n", 2, "renderer must be cpu, gl or auto");
  expect_error_on_line("renderer gl now\n", 1, "unexpected 'now'");
  expect_error_on_line("shading gouraud\n", 1, "shading must be pixel or vertex");
  expect_error_on_line("shadow-map 15\n", 1, "shadow-map must be 16..4096 texels");
  expect_error_on_line("shadow-map 4097\n", 1, "shadow-map must be 16..4096 texels");
  expect_error_on_line("shadow-map 1e9\n", 1, "shadow-map must be 16..4096 texels");
  expect_error_on_line("shadow-map 512.5\n", 1, "whole number");
  expect_error_on_line("shadow-bias -0.5\n", 1, "shadow-bias must be a finite number");
  expect_error_on_line("shadow-bias inf\n", 1, "shadow-bias must be a finite number");
  expect_error_on_line("shadow-bias nan\n", 1, "shadow-bias must be a finite number");
  expect_error_on_line("view ab gl\n", 1, "'snapshot', 'cpu-gl', 'pixel-vertex' or 'reference'");
}

TEST(Script, ParsesMouseGestures) {
  const Script s = parse_script(
      "mouse press 0.5 0.25\nmouse press 0 1 right\nmouse move 1 0\nmouse release\n", "m.txt");
  ASSERT_EQ(s.lines.size(), 4u);
  const auto& press = std::get<MouseAction>(s.lines[0].action);
  EXPECT_EQ(press.verb, MouseAction::Verb::press);
  EXPECT_EQ(press.x, 0.5f);
  EXPECT_EQ(press.y, 0.25f);
  EXPECT_EQ(press.button, 0);  // left unless named
  EXPECT_EQ(std::get<MouseAction>(s.lines[1].action).button, 1);
  const auto& move = std::get<MouseAction>(s.lines[2].action);
  EXPECT_EQ(move.verb, MouseAction::Verb::move);
  EXPECT_EQ(move.x, 1.0f);
  EXPECT_EQ(move.y, 0.0f);
  EXPECT_EQ(std::get<MouseAction>(s.lines[3].action).verb, MouseAction::Verb::release);
}

TEST(Script, BadMouseLinesNameTheLine) {
  expect_error_on_line("mouse\n", 1, "missing mouse action");
  expect_error_on_line("wait\nmouse click 0.5 0.5\n", 2, "mouse must be 'press X Y");
  expect_error_on_line("mouse press 0.5\n", 1, "missing y");
  expect_error_on_line("mouse move 1.5 0.5\n", 1, "fractions of the viewport image, 0..1");
  expect_error_on_line("mouse move 0.5 nan\n", 1, "fractions of the viewport image, 0..1");
  expect_error_on_line("mouse press 0.5 0.5 thumb\n", 1, "left, right or middle");
  expect_error_on_line("mouse move 0.5 0.5 left\n", 1, "unexpected 'left'");
  expect_error_on_line("mouse release now\n", 1, "unexpected 'now'");
}

TEST(Script, RendererAndRasterLinesSetTheViewSettings) {
  RecordingHost host(test::two_sphere_scene());
  std::string errors;
  const LineResult r =
      run_all("renderer auto\nshading vertex\nshadow-map 256\nshadow-bias 0.75\nview ab cpu-gl\n",
              host, errors);
  EXPECT_EQ(r.next, LineResult::Next::go_on) << errors;
  EXPECT_EQ(host.view().renderer, RendererChoice::automatic);
  EXPECT_EQ(host.view().raster.shading, ShadingFrequency::vertex);
  EXPECT_EQ(host.view().raster.shadow_map_size, 256);
  EXPECT_EQ(host.view().raster.shadow_bias, 0.75f);
  EXPECT_EQ(host.view().mode, ViewMode::ab);
  EXPECT_EQ(host.view().ab_source, AbSource::cpu_gl);
  run_all("view ab pixel-vertex\nrenderer cpu\n", host, errors);
  EXPECT_EQ(host.view().ab_source, AbSource::pixel_vertex);
  EXPECT_EQ(host.view().renderer, RendererChoice::cpu);
  // View settings are not document edits: nothing to undo.
  EXPECT_EQ(host.layer().undo_count(), 0u);
}

TEST(Script, QuitStopsWithStatusZero) {
  RecordingHost host(test::two_sphere_scene());
  std::string errors;
  const LineResult r = run_all("quit\nset 0 shininess 5\n", host, errors);
  EXPECT_EQ(r.next, LineResult::Next::stop);
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(host.layer().scene().materials[0].shininess, 5.0f);
}

}  // namespace
}  // namespace gloss
