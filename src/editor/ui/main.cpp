// gloss: the live Phong material editor. Setup (options, scene, window, GL, ImGui), Main loop
// (events, one frame), Cleanup. Without a display it renders the scene to a PNG instead.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <glad/gl.h>
#include <imgui.h>
#include <CLI/CLI.hpp>

#include "base/assets.h"
#include "base/error.h"
#include "base/process_memory.h"
#include "editor/model/document/document.h"
#include "editor/model/script/headless.h"
#include "editor/model/session/config_paths.h"
#include "editor/ui/app.h"
#include "editor/ui/script_player.h"
#include "editor/ui/shortcuts.h"
#include "io/scene/scene_loader.h"

namespace {

struct Options {
  std::string scene_path;   // empty: the shipped default scene, else the built-in one
  std::string script_path;  // empty: interactive
  bool no_recovery = false;
  std::string recovery_path;       // empty: default_recovery_file()
  int width = 1280, height = 800;  // window size, screen pixels
};

// Set by GLFW's error callback: the reason shown when there is no display.
std::string g_glfw_error;

void on_glfw_error(int code, const char* description) {
  g_glfw_error = description != nullptr ? description : "GLFW error " + std::to_string(code);
}

gloss::Scene load_start_scene(const Options& options) {
  if (!options.scene_path.empty()) return gloss::load_scene(options.scene_path);
  const std::string shipped = gloss::asset_path("scenes/spheres.json");
  std::error_code ec;
  if (std::filesystem::exists(shipped, ec)) return gloss::load_scene(shipped);
  return gloss::builtin_scene();
}

}  // namespace

int main(int argc, char** argv) {
  gloss::limit_allocator_retention();  // before any thread (renderers, llvmpipe) starts
  using namespace gloss;
  // ---- Setup: options, document, script -----------------------------------------------------
  Options options;
  // The guide's full path: the installed share/doc/gloss, or the source tree's docs/ in a build.
  const std::string guide = doc_path("editor.md");
  CLI::App cli{
      "gloss: live Phong material editor. Opens SCENE.json, or a PNG gloss wrote (its "
      "embedded scene), in a window (default: the shipped spheres scene); press F1 inside for "
      "shortcuts. Without a display it renders the scene to a PNG in the current folder. "
      "Guide: " +
      guide};
  cli.add_option("scene", options.scene_path,
                 "scene file (JSON, " + doc_path("scene-format.md") + ") or a PNG gloss wrote");
  cli.add_option("--script", options.script_path,
                 "replay commands from FILE, one per line (" + guide + " lists them)");
  cli.add_flag("--no-recovery", options.no_recovery,
               "neither offer nor write the crash-recovery file");
  cli.add_option("--recovery-file", options.recovery_path,
                 "autosave to FILE instead of the state folder's recovery.json; with --script, "
                 "autosave runs too (to test it), without offering the file back");
  cli.add_option("--window-width", options.width, "window width, pixels")
      ->check(CLI::Range(320, 8192));
  cli.add_option("--window-height", options.height, "window height, pixels")
      ->check(CLI::Range(240, 8192));
  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version arrive as "errors" with exit code 0; CLI11 prints them. Anything else
    // is one error line, as every other bad input is.
    if (e.get_exit_code() == 0) return cli.exit(e);
    std::fprintf(stderr, "error: %s (gloss --help lists the options)\n", e.what());
    return 2;
  }
  std::optional<Scene> scene;
  std::optional<Script> script;
  try {
    scene = load_start_scene(options);
    if (!options.script_path.empty()) script = load_script(options.script_path);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }

  // ---- Setup: window and GL; without them, the CPU renderer alone ------------------------
  glfwSetErrorCallback(on_glfw_error);
  if (!glfwInit()) {
    return script ? run_script_without_display(*scene, *script, g_glfw_error)
                  : render_without_display(*scene, g_glfw_error);
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  GLFWwindow* window = glfwCreateWindow(options.width, options.height, "gloss", nullptr, nullptr);
  if (window == nullptr) {
    const std::string reason = "no OpenGL 3.3 core window: " + g_glfw_error;
    glfwTerminate();
    return script ? run_script_without_display(*scene, *script, reason)
                  : render_without_display(*scene, reason);
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(1);
  if (gladLoadGL(glfwGetProcAddress) == 0) {
    std::fprintf(stderr, "error: cannot load OpenGL 3.3 functions\n");
    glfwDestroyWindow(window);
    glfwTerminate();
    return 1;
  }
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  // Scripts run with the default layout so their window screenshots do not depend on the user's.
  const std::string ini_path = (config_dir() / "imgui.ini").string();
  io.IniFilename = script ? nullptr : ini_path.c_str();
  ImGui::StyleColorsDark();
  install_input_callbacks(window);  // before the backend, which chains to what it finds
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");

  int status = 0;
  try {
    App app(window, std::move(*scene));
    if (script) {
      app.run.script = std::make_unique<ScriptPlayer>(std::move(*script));
      if (!options.recovery_path.empty()) {
        app.session.autosaver.emplace(options.recovery_path, app.document.revision());
      }
    } else if (!options.no_recovery) {
      const std::filesystem::path recovery_file =
          options.recovery_path.empty() ? default_recovery_file()
                                        : std::filesystem::path(options.recovery_path);
      try {
        app.session.offered_recovery = read_recovery(recovery_file);
      } catch (const std::exception& e) {
        app.notices.error(std::string("ignored a damaged recovery file: ") + e.what(), 0.0);
      }
      app.session.autosaver.emplace(recovery_file, app.document.revision());
    }

    // ---- Main loop ----------------------------------------------------------------------------
    int settle = 2;  // frames drawn after an event so ImGui's hover and popups catch up
    while (!app.run.quit) {
      const double timeout = idle_timeout(app);
      if (settle > 0 || timeout <= 0.0) {
        glfwPollEvents();
        settle = settle > 0 ? settle - 1 : 0;
      } else {
        glfwWaitEventsTimeout(timeout);
        settle = 2;
      }
      run_frame(app);
    }

    // ---- Cleanup ------------------------------------------------------------------------------
    if (!app.exports.finish()) app.run.exit_code = 1;
    // A clean exit needs no recovery (unsaved changes were saved or declined in the quit dialog).
    if (app.session.autosaver) app.session.autosaver->discard();
    status = app.run.exit_code;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    status = 1;
  }
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
  glfwTerminate();
  return status;
}
