#include "editor/ui/app.h"

#include <algorithm>

#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <glad/gl.h>
#include <imgui.h>

#include "base/process_memory.h"
#include "editor/model/session/config_paths.h"
#include "editor/model/session/file_defaults.h"
#include "editor/model/session/material_library_folder.h"
#include "editor/model/view/camera_controller.h"
#include "editor/model/view/light_gizmo.h"
#include "editor/ui/panels/quality_parts.h"
#include "editor/ui/script_player.h"
#include "editor/ui/shortcuts.h"

namespace gloss {

App::App(GLFWwindow* glfw_window, Scene scene) : window(glfw_window), document(std::move(scene)) {
  glfwSetWindowUserPointer(window, &input);  // the key queue's callbacks find it here
  session.config_folder = config_dir();
  session.recent = load_recent_lists(session.config_folder);
  std::error_code ec;
  // Screenshots go where gloss was started, unless that is the shipped assets' folder.
  view.screenshot_dir = save_folder(std::filesystem::current_path(ec)).string();
  library.swatches.start();
  session.browser.last_folder = load_last_folder(session.config_folder);
  library.folder = library_folder();
  files.reload_library();
}

App::~App() {
  glfwSetWindowUserPointer(window, nullptr);
}

namespace {

void animate_light(App& app, double now_s) {
  const Scene& scene = app.document.scene();
  if (!app.view.orbit_light || scene.lights.empty()) return;
  int& light_index = app.selection.light;
  light_index = std::clamp(light_index, 0, static_cast<int>(scene.lights.size()) - 1);
  // Steps longer than 0.1 s (a stalled frame) are cut so the light never jumps.
  const float dt = static_cast<float>(std::min(now_s - app.frame.last_frame_s, 0.1));
  const Light light = scene.lights[light_index];  // a copy: commands replace the vector
  // A point light's position, a spot's position and direction, a directional light's direction
  // turn about the vertical axis through the target (light_gizmo.h).
  const Light turned = orbited_light(light, scene.camera.target, app.view.orbit_speed * dt);
  if (turned.position != light.position) {
    app.commands.execute(
        SetField{FieldPart::light, light_index, "position", vec3_value(turned.position)});
  }
  if (turned.direction != light.direction) {
    app.commands.execute(
        SetField{FieldPart::light, light_index, "direction", vec3_value(turned.direction)});
  }
}

void update_title(App& app) {
  const std::string& path = app.document.scene().path;
  std::string title = "gloss - " + (path.empty() ? std::string("untitled")
                                                 : std::filesystem::path(path).filename().string());
  if (app.document.dirty()) title += " *";
  if (title != app.frame.title) {
    glfwSetWindowTitle(app.window, title.c_str());
    app.frame.title = title;
  }
}

// Announces an autosave failure once when it appears or changes; the status bar keeps it on
// screen (autosave_notice) until a write succeeds.
void autosave(App& app, double now_s) {
  Session& session = app.session;
  if (!session.autosaver) return;
  session.autosaver->step(app.document, app.selection.object, now_s);
  const std::string& failure = session.autosaver->failure();
  if (!failure.empty() && failure != session.autosave_failure_shown) {
    app.notices.error("autosave failed: " + failure, now_s);
  } else if (failure.empty() && !session.autosave_failure_shown.empty()) {
    app.notices.info("autosave works again", now_s);
  }
  session.autosave_failure_shown = failure;
}

}  // namespace

void run_frame(App& app) {
  const double frame_start = app.now_s();
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  replay_key_taps(app.input, app.window);
  replay_script_mouse(app.input, app.viewport);
  ImGui::NewFrame();

  app.notices.expire(frame_start);
  // New threads (a renderer for the A/B view, exports) are lowered within a quarter second.
  if (frame_start - app.frame.background_checked_s > 0.25) {
    app.frame.background.update();
    app.frame.background_checked_s = frame_start;
  }
  app.viewport.upload_frames(frame_start);
  app.library.swatches.poll();
  app.library.balls.poll();
  app.quality.cpu.poll();
  app.quality.raster.step(kRasterQualitySliceMs);  // GL: this thread owns the context
  if (app.exports.poll()) {                        // an export a script started failed
    app.run.exit_code = 1;
    app.run.quit = true;
  }
  if (app.run.script) {
    app.run.script->step(app);
    if (app.run.script->finished() && !app.run.quit) {
      app.run.script.reset();                  // the editor stays open
      app.input.script_mouse = ScriptMouse{};  // and the real mouse is the user's again
    }
  }
  handle_shortcuts(app);
  animate_light(app, frame_start);
  draw_layout(app);

  // A gesture (slider drag, viewport drag, animation) is one undo step; it ends here.
  if (!ImGui::IsAnyItemActive() && !app.viewport.gesture_active(frame_start) &&
      !app.view.orbit_light) {
    app.document.seal();
  }
  app.viewport.sync(app.document.scene(), app.document.revision(), app.view,
                    app.snapshot ? &*app.snapshot : nullptr, frame_start);
  if (const std::string raster = app.viewport.take_raster_notice(); !raster.empty()) {
    app.notices.error(raster, frame_start);
  }
  // Once an edit's image has converged and is on screen the editor idles: the memory its passes
  // freed goes back to the system (a few ms, once per converged image).
  if (app.viewport.uploads() != app.frame.released_at_upload &&
      app.viewport.converged_and_shown(app.document.revision(), app.view)) {
    release_free_memory();
    app.frame.released_at_upload = app.viewport.uploads();
  }
  autosave(app, frame_start);
  update_title(app);
  if (glfwWindowShouldClose(app.window)) {
    glfwSetWindowShouldClose(app.window, GLFW_FALSE);
    app.files.request_quit();
  }

  ImGui::Render();
  int fb_width = 0, fb_height = 0;
  glfwGetFramebufferSize(app.window, &fb_width, &fb_height);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, fb_width, fb_height);
  glClearColor(0.08f, 0.08f, 0.09f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  app.viewport.blit(fb_height);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  app.exports.capture_if_due(app.window);
  glfwSwapBuffers(app.window);

  const double frame_end = app.now_s();
  app.viewport.frame_shown(frame_end);
  app.frame.times.add((frame_end - frame_start) * 1000.0);
  app.frame.last_frame_s = frame_start;
}

double idle_timeout(const App& app) {
  const double now = app.now_s();
  if (app.exports.capture_requested() || app.viewport.gesture_active(now)) return 0.0;
  // Published frames wake the loop at once (glfwPostEmptyEvent); these short timeouts cover
  // what does not: the animation's next step (60 Hz), exports finishing, a script's next line.
  if (app.view.orbit_light) return 1.0 / 60.0;
  if (app.run.script || app.exports.running()) return 0.02;
  if (app.quality.cpu.running()) return 0.1;         // rows arrive and the elapsed time counts up
  if (app.library.balls.pending() > 0) return 0.05;  // material swatches rendering
  // Raster rows are drawn a slice per frame; while the worker renders their references, the
  // progress only needs refreshing.
  if (app.quality.raster.state() == RasterTradeoff::State::rendering) return 0.0;
  if (app.quality.raster.running()) return 0.1;
  double timeout = 0.5;  // keeps hover states and the status bar fresh without spinning
  for (const Notice& n : app.notices.items) timeout = std::min(timeout, n.until_s - now);
  return std::max(timeout, 0.0);
}

}  // namespace gloss
