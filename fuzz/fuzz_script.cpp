// libFuzzer target: the editor's script language (editor/model/script/script.h, script_runner.h).
// The text is parsed, then every line runs through run_script_line on a host without GL (the editor
// model is GL-free) against a small scene: spheres, a quad and a teapot. The host's waits,
// screenshots, stats, sleeps and quality measurements do nothing (no renders, no files); what is
// fuzzed is the parser, the dispatcher and the command layer with its undo. At the end the edited
// document must still be savable and read back (the autosave's promise).
#include <cstdint>
#include <string>

#include "base/error.h"
#include "editor/model/document/command_layer.h"
#include "editor/model/script/script.h"
#include "editor/model/script/script_runner.h"
#include "fuzz_input.h"
#include "io/scene/scene_loader.h"

namespace {

const char* const kScene = R"({
  "camera": {"eye": [0, 2.2, 7.5], "target": [0, 0.8, 0], "up": [0, 1, 0], "fov_y": 35},
  "ambient": [0.2, 0.2, 0.2],
  "lights": [{"position": [5, 7, 6], "diffuse": [1, 1, 1], "specular": [1, 1, 1]}],
  "materials": {"gold": {"preset": "gold"}, "floor": {"diffuse": [0.5, 0.5, 0.5]}},
  "objects": [
    {"type": "sphere", "center": [-1.15, 1, 0], "radius": 1, "material": "gold"},
    {"type": "quad", "vertices": [[-8, 0, -8], [8, 0, -8], [8, 0, 6], [-8, 0, 6]],
     "material": "floor"},
    {"type": "teapot", "position": [1.2, 0, 0], "scale": 0.3, "tessellation": 2,
     "material": "gold"}
  ],
  "render": {"width": 64, "height": 48, "spp": 1}
})";

class FuzzHost : public gloss::ScriptHost {
 public:
  explicit FuzzHost(const gloss::Scene& scene) : m_layer(scene) {}
  gloss::CommandLayer& layer() override { return m_layer; }
  gloss::ViewSettings& view() override { return m_view; }
  void select(int) override {}
  gloss::LineResult wait(const gloss::WaitAction&, const std::string&) override { return {}; }
  gloss::LineResult screenshot(const gloss::ScreenshotAction&, const std::string&) override {
    return {};
  }
  gloss::LineResult stats() override { return {}; }
  gloss::LineResult sleep(const gloss::SleepAction&) override { return {}; }
  gloss::LineResult quality(const gloss::QualityAction&, const std::string&) override { return {}; }
  // `save PATH` writes no file here (any path the fuzzer makes up).
  gloss::LineResult save(const gloss::SaveAction&, const std::string&) override { return {}; }

 private:
  gloss::CommandLayer m_layer;
  gloss::ViewSettings m_view;
};

const gloss::Scene& base_scene() {
  static const gloss::Scene scene =
      gloss::parse_scene(kScene, (gloss_fuzz::temp_dir() / "scene.json").string());
  return scene;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  base_scene();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  gloss::Script script;
  try {
    script = gloss::parse_script(text, "fuzz.txt");
  } catch (const gloss::InputError&) {
    return 0;
  }
  FuzzHost host(base_scene());
  for (const gloss::ScriptLine& line : script.lines) {
    if (gloss::run_script_line(script, line, host).next == gloss::LineResult::Next::stop) break;
  }
  const std::string path = (gloss_fuzz::temp_dir() / "saved.json").string();
  try {
    gloss::parse_scene(gloss::scene_to_json_text(host.layer().scene()), path);
  } catch (const gloss::InputError& e) {
    // A document the editor holds must save and read back: a refusal here is a finding.
    std::fprintf(stderr, "gloss-fuzz: the edited scene does not read back: %s\n", e.what());
    std::abort();
  }
  return 0;
}
