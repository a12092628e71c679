// The lobe view's and the pixel inspector's script verbs (docs/editor.md): `view lobe
// [ELEVATION_DEG]` and `inspect X Y`, parsed, run through the dispatcher, and the printed
// reading's format.
#include <cmath>
#include <map>
#include <sstream>
#include <vector>

#include <gtest/gtest.h>

#include "base/error.h"
#include "editor/model/document/command_layer.h"
#include "editor/model/script/script.h"
#include "editor/model/script/script_runner.h"
#include "reference/reference_renderer.h"
#include "support/quiet_script_host.h"
#include "support/test_scene.h"

namespace gloss {
namespace {

using Host = test::QuietScriptHost;

struct ScriptRun {
  LineResult result;
  std::string out, err;
};

ScriptRun run(const std::string& text, Host& host) {
  const Script s = parse_script(text, "run.txt");
  ScriptRun r;
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  for (const ScriptLine& line : s.lines) {
    r.result = run_script_line(s, line, host);
    if (r.result.next == LineResult::Next::stop) break;
  }
  r.err = testing::internal::GetCapturedStderr();
  r.out = testing::internal::GetCapturedStdout();
  return r;
}

void expect_parse_error(const std::string& text, const std::string& words) {
  try {
    parse_script(text, "bad.txt");
    ADD_FAILURE() << "no error for: " << text;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST(LobeAndInspectScript, Parse) {
  const Script s = parse_script("view lobe\nview lobe 30\ninspect 3 4\n", "s.txt");
  ASSERT_EQ(s.lines.size(), 3u);
  EXPECT_EQ(std::get<ViewAction>(s.lines[0].action).mode, ViewMode::lobe);
  EXPECT_EQ(std::get<ViewAction>(s.lines[0].action).lobe_elevation_deg, -1.0f);
  EXPECT_EQ(std::get<ViewAction>(s.lines[1].action).lobe_elevation_deg, 30.0f);
  EXPECT_EQ(std::get<InspectAction>(s.lines[2].action).x, 3);
  EXPECT_EQ(std::get<InspectAction>(s.lines[2].action).y, 4);
  expect_parse_error("view lobe 95\n", "0..90 degrees");
  expect_parse_error("view lobe high\n", "expected a number");
  expect_parse_error("inspect 3\n", "missing pixel y");
  expect_parse_error("inspect -1 2\n", "expected an index for pixel x");
  expect_parse_error("view sideways\n", "render, terms, ab, lobe");
}

TEST(LobeAndInspectScript, ViewLobeSetsTheModeAndElevation) {
  Host host(test::two_sphere_scene());
  run("view lobe 30\nview render\nview lobe\n", host);
  EXPECT_EQ(host.view().mode, ViewMode::lobe);
  EXPECT_EQ(host.view().lobe_elevation_deg, 30.0f);  // a bare `view lobe` keeps it
}

// The lines of a reading: name -> numbers, in the order printed.
struct Reading {
  std::vector<std::string> names;
  std::map<std::string, std::vector<double>> numbers;
  std::map<std::string, std::string> words;
};

Reading read(const std::string& out) {
  Reading r;
  std::istringstream in(out);
  for (std::string line; std::getline(in, line);) {
    std::istringstream words(line);
    std::string name;
    words >> name;
    r.names.push_back(name);
    const std::string rest = line.substr(std::min(line.size(), name.size() + 1));
    r.words[name] = rest;
    std::istringstream values(rest);
    for (double v; values >> v;) r.numbers[name].push_back(v);
  }
  return r;
}

// Pixel (15, 16) of the two-sphere scene's 64 x 48 render sees the left sphere (red material)
// under both lights. The printed reading has every line of docs/editor.md in order, and its
// numbers hang together as the contract says: each light's diffuse is kd Ld ndl att vis, its
// specular ks Ls c_alpha att vis, the terms sum to the total, and the total is the reference
// renderer's pixel. ndl by hand (camera.h's ray for the pixel centre, the ray-sphere root, the
// sphere normal): light 0 0.559512, light 1 0.494857.
TEST(LobeAndInspectScript, InspectPrintsTheReading) {
  const Scene scene = test::two_sphere_scene();
  Host host(scene);
  const ScriptRun r = run("inspect 15 16\n", host);
  EXPECT_EQ(r.result.next, LineResult::Next::go_on);
  EXPECT_EQ(r.err, "");
  const Reading reading = read(r.out);
  const std::vector<std::string> expected = {"pixel",          "object",
                                             "material",       "alpha",
                                             "energy_factor",  "total",
                                             "emissive",       "ambient",
                                             "diffuse",        "specular",
                                             "light0.ndl",     "light0.c",
                                             "light0.c_alpha", "light0.attenuation",
                                             "light0.spot",    "light0.visibility",
                                             "light0.diffuse", "light0.specular",
                                             "light1.ndl",     "light1.c",
                                             "light1.c_alpha", "light1.attenuation",
                                             "light1.spot",    "light1.visibility",
                                             "light1.diffuse", "light1.specular"};
  EXPECT_EQ(reading.names, expected) << r.out;
  EXPECT_EQ(reading.words.at("pixel"), "15 16 64x48");
  EXPECT_EQ(reading.words.at("object"), "left");
  EXPECT_EQ(reading.words.at("material"), "red");
  EXPECT_EQ(reading.numbers.at("alpha"), std::vector<double>{64.0});
  for (const char* rgb : {"total", "emissive", "ambient", "diffuse", "specular", "light0.diffuse",
                          "light0.specular", "light1.diffuse", "light1.specular"}) {
    EXPECT_EQ(reading.numbers.at(rgb).size(), 3u) << rgb;
  }
  const Material& red = scene.materials[0];
  glm::dvec3 diffuse(0.0), specular(0.0);
  for (int i = 0; i < 2; ++i) {
    const std::string l = "light" + std::to_string(i) + ".";
    const double ndl = reading.numbers.at(l + "ndl")[0];
    const double c_alpha = reading.numbers.at(l + "c_alpha")[0];
    const double att = reading.numbers.at(l + "attenuation")[0];
    const double vis = reading.numbers.at(l + "visibility")[0];
    EXPECT_EQ(reading.numbers.at(l + "spot"), std::vector<double>{1.0}) << l;  // point lights
    EXPECT_NEAR(ndl, i == 0 ? 0.559512 : 0.494857, 1e-5) << l;
    EXPECT_NEAR(c_alpha, std::pow(reading.numbers.at(l + "c")[0], 64.0), 1e-7) << l;
    const PointLight& light = scene.lights[static_cast<std::size_t>(i)];
    for (int k = 0; k < 3; ++k) {
      const double d = reading.numbers.at(l + "diffuse")[static_cast<std::size_t>(k)];
      const double s = reading.numbers.at(l + "specular")[static_cast<std::size_t>(k)];
      EXPECT_NEAR(d, red.diffuse[k] * light.diffuse[k] * ndl * att * vis, 1e-7) << l << k;
      EXPECT_NEAR(s, red.specular[k] * light.specular[k] * c_alpha * att * vis, 1e-7) << l << k;
      diffuse[k] += d;
      specular[k] += s;
    }
  }
  ReferenceOptions one;
  one.spp = 1;
  const glm::vec3 pixel = render_reference<double>(scene, one).total.at(15, 16);
  for (int k = 0; k < 3; ++k) {
    const auto at = static_cast<std::size_t>(k);
    EXPECT_NEAR(reading.numbers.at("diffuse")[at], diffuse[k], 1e-7);
    EXPECT_NEAR(reading.numbers.at("specular")[at], specular[k], 1e-7);
    const double sum = reading.numbers.at("emissive")[at] + reading.numbers.at("ambient")[at] +
                       reading.numbers.at("diffuse")[at] + reading.numbers.at("specular")[at];
    EXPECT_NEAR(reading.numbers.at("total")[at], sum, 1e-7);
    EXPECT_NEAR(reading.numbers.at("total")[at], pixel[k], 1e-6);
  }
  // The editor's inspector is pinned where the script looked.
  EXPECT_TRUE(host.view().show_inspector);
  EXPECT_TRUE(host.view().inspect_pinned);
  EXPECT_EQ(host.view().inspect_x, 15);
  EXPECT_EQ(host.view().inspect_y, 16);
}

TEST(LobeAndInspectScript, AMissReadsTheBackground) {
  Host host(test::two_sphere_scene());
  const Reading reading = read(run("inspect 0 0\n", host).out);
  EXPECT_EQ(reading.words.at("object"), "none");
  ASSERT_EQ(reading.numbers.at("total").size(), 3u);
  for (double v : reading.numbers.at("total")) EXPECT_NEAR(v, 0.1, 1e-8);
  EXPECT_EQ(reading.numbers.count("light0.ndl"), 0u);
}

TEST(LobeAndInspectScript, APixelOutsideTheRenderIsABadLine) {
  Host host(test::two_sphere_scene());
  const ScriptRun r = run("inspect 64 0\n", host);
  EXPECT_EQ(r.result.status, 2);
  EXPECT_EQ(r.err, "error: run.txt:1: pixel 64 0 is outside the 64x48 render\n");
  EXPECT_EQ(r.out, "");
}

}  // namespace
}  // namespace gloss
