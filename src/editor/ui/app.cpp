#include "editor/ui/app.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include "base/error.h"
#include "base/process_memory.h"
#include "editor/model/session/config_paths.h"
#include "editor/model/view/camera_controller.h"
#include "editor/ui/panels/quality_parts.h"
#include "editor/ui/script_player.h"

namespace gloss {

void FrameTimes::add(double value) {
  ms[next] = value;
  next = (next + 1) % kCount;
  size = std::min(size + 1, kCount);
}

double FrameTimes::average() const {
  double sum = 0.0;
  for (int i = 0; i < size; ++i) sum += ms[i];
  return size > 0 ? sum / size : 0.0;
}

double FrameTimes::median() const {
  if (size == 0) return 0.0;
  std::vector<double> sorted(ms, ms + size);
  std::nth_element(sorted.begin(), sorted.begin() + size / 2, sorted.end());
  return sorted[size / 2];
}

double FrameTimes::largest() const {
  double top = 0.0;
  for (int i = 0; i < size; ++i) top = std::max(top, ms[i]);
  return top;
}

App::App(GLFWwindow* glfw_window, Scene scene) : window(glfw_window), commands(std::move(scene)) {
  glfwSetWindowUserPointer(window, this);  // the key queue's callback finds the App here
  config_folder = config_dir();
  recent = load_recent_lists(config_folder);
  std::error_code ec;
  view.screenshot_dir = std::filesystem::current_path(ec).string();
  swatches.start();
}

App::~App() {
  glfwSetWindowUserPointer(window, nullptr);
}

double App::now_s() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

bool execute(App& app, const Command& command) {
  try {
    return app.commands.execute(command);
  } catch (const CommandError& e) {
    app.notices.error(e.what(), app.now_s());
    return false;
  }
}

namespace {

void animate_light(App& app, double now_s) {
  const Scene& scene = app.commands.scene();
  if (!app.view.orbit_light || scene.lights.empty()) return;
  app.selected_light = std::clamp(app.selected_light, 0, static_cast<int>(scene.lights.size()) - 1);
  // Steps longer than 0.1 s (a stalled frame) are cut so the light never jumps.
  const float dt = static_cast<float>(std::min(now_s - app.last_frame_s, 0.1));
  const PointLight light = scene.lights[app.selected_light];  // a copy: commands replace the vector
  const glm::vec3 centre(scene.camera.target.x, light.position.y, scene.camera.target.z);
  execute(app,
          SetField{FieldPart::light, app.selected_light, "position",
                   vec3_value(rotate_about_y(light.position, centre, app.view.orbit_speed * dt))});
}

void draw_recovery_modal(App& app) {
  if (!app.offered_recovery) return;
  const char* id = "Recover unsaved session?";
  if (!ImGui::IsPopupOpen(id)) ImGui::OpenPopup(id);
  if (!ImGui::BeginPopupModal(id, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  const Recovery& r = *app.offered_recovery;
  ImGui::TextUnformatted("gloss did not exit cleanly last time.");
  ImGui::Text("An autosaved session from %s is available", r.saved_at.c_str());
  ImGui::Text("(scene: %s).", r.scene.path.empty() ? "not saved to a file" : r.scene.path.c_str());
  ImGui::Separator();
  if (ImGui::Button("Recover", ImVec2(140, 0))) {
    app.commands.reset(r.scene, false);
    app.selected_object = std::max(0, r.selected_object);
    app.notices.info("recovered the autosaved session", app.now_s());
    app.offered_recovery.reset();
    ImGui::CloseCurrentPopup();
  }
  ImGui::SameLine();
  if (ImGui::Button("Discard", ImVec2(140, 0))) {
    if (app.autosaver) app.autosaver->discard();
    app.offered_recovery.reset();
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

void draw_quit_modal(App& app) {
  if (!app.confirm_quit) return;
  const char* id = "Unsaved changes";
  if (!ImGui::IsPopupOpen(id)) ImGui::OpenPopup(id);
  if (!ImGui::BeginPopupModal(id, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  const std::string& path = app.commands.scene().path;
  ImGui::TextUnformatted("The scene has changes that are not saved.");
  if (!path.empty() && ImGui::Button("Save and quit", ImVec2(150, 0))) {
    try {
      save_scene_as(app, path);
      app.quit = true;
    } catch (const std::exception& e) {
      app.notices.error(e.what(), app.now_s());
    }
    app.confirm_quit = false;
    ImGui::CloseCurrentPopup();
  }
  if (!path.empty()) ImGui::SameLine();
  if (ImGui::Button("Quit without saving", ImVec2(150, 0))) {
    app.quit = true;
    app.confirm_quit = false;
    ImGui::CloseCurrentPopup();
  }
  ImGui::SameLine();
  if (ImGui::Button("Cancel", ImVec2(150, 0))) {
    app.confirm_quit = false;
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

// Opening another scene with unsaved changes: save / discard / cancel (UnsavedGuard's rules).
void draw_open_modal(App& app) {
  if (!app.unsaved.asking()) return;
  const char* id = "Open another scene";
  if (!ImGui::IsPopupOpen(id)) ImGui::OpenPopup(id);
  if (!ImGui::BeginPopupModal(id, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  const std::string& path = app.commands.scene().path;
  ImGui::TextUnformatted("The scene has changes that are not saved.");
  ImGui::Text("Open %s anyway?",
              std::filesystem::path(app.unsaved.waiting_path()).filename().string().c_str());
  if (path.empty()) ImGui::TextDisabled("(untitled: use Save scene as... first to keep them)");
  std::optional<UnsavedAnswer> answer;
  if (!path.empty() && ImGui::Button("Save, then open", ImVec2(150, 0))) {
    answer = UnsavedAnswer::save;
  }
  if (!path.empty()) ImGui::SameLine();
  if (ImGui::Button("Discard changes", ImVec2(150, 0))) answer = UnsavedAnswer::discard;
  ImGui::SameLine();
  if (ImGui::Button("Cancel", ImVec2(150, 0)) ||
      ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) {
    answer = UnsavedAnswer::cancel;
  }
  if (answer) {
    ImGui::CloseCurrentPopup();
    const UnsavedGuard::Outcome outcome = app.unsaved.answer(*answer);
    try {
      if (outcome.save_first) save_scene_as(app, path);
      if (outcome.open) open_scene(app, outcome.path);
    } catch (const std::exception& e) {
      app.notices.error(e.what(), app.now_s());
    }
  }
  ImGui::EndPopup();
}

void update_title(App& app) {
  const std::string& path = app.commands.scene().path;
  std::string title = "gloss - " + (path.empty() ? std::string("untitled")
                                                 : std::filesystem::path(path).filename().string());
  if (app.commands.dirty()) title += " *";
  if (title != app.title) {
    glfwSetWindowTitle(app.window, title.c_str());
    app.title = title;
  }
}

// A thin handle over the border between two panels: dragging it moves the border. vertical:
// a left-right border (moved along x), else a top-bottom one. Returns the drag this frame.
float splitter(const char* id, ImVec2 pos, ImVec2 size, bool vertical) {
  ImGui::SetNextWindowPos(pos);
  ImGui::SetNextWindowSize(size);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowMinSize, ImVec2(1, 1));
  ImGui::Begin(id, nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoBackground |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing);
  ImGui::PopStyleVar(2);
  ImGui::InvisibleButton("##handle", size);
  float moved = 0.0f;
  if (ImGui::IsItemHovered() || ImGui::IsItemActive()) {
    ImGui::SetMouseCursor(vertical ? ImGuiMouseCursor_ResizeEW : ImGuiMouseCursor_ResizeNS);
    ImGui::GetWindowDrawList()->AddRectFilled(
        pos, ImVec2(pos.x + size.x, pos.y + size.y),
        ImGui::GetColorU32(ImGui::IsItemActive() ? ImGuiCol_SeparatorActive
                                                 : ImGuiCol_SeparatorHovered));
  }
  if (ImGui::IsItemActive())
    moved = vertical ? ImGui::GetIO().MouseDelta.x : ImGui::GetIO().MouseDelta.y;
  ImGui::End();
  return moved;
}

void draw_layout(App& app) {
  draw_menu_bar(app);
  const ImGuiViewport* main = ImGui::GetMainViewport();
  const float menu_h = ImGui::GetFrameHeight();
  const float status_h = ImGui::GetFrameHeight() + 6.0f;
  const float top = main->Pos.y + menu_h;
  const float height = std::max(main->Size.y - menu_h - status_h, 1.0f);
  const float default_side = std::clamp(main->Size.x * 0.23f, 280.0f, 420.0f);
  // Each side panel keeps between 220 pixels and 40% of the window.
  const float most = std::max(220.0f, main->Size.x * 0.4f);
  if (app.left_width <= 0.0f) app.left_width = default_side;
  if (app.right_width <= 0.0f) app.right_width = default_side;
  app.left_width = std::clamp(app.left_width, 220.0f, most);
  app.right_width = std::clamp(app.right_width, 220.0f, most);
  app.lights_share = std::clamp(app.lights_share, 0.15f, 0.85f);
  const float side = app.left_width;
  const float right_side = app.right_width;
  const float left = main->Pos.x, right = main->Pos.x + main->Size.x;
  const float lights_h = std::floor(height * app.lights_share);
  draw_material_panel(app, ImVec2(left, top), ImVec2(side, height));
  draw_lights_panel(app, ImVec2(right - right_side, top), ImVec2(right_side, lights_h));
  draw_view_panel(app, ImVec2(right - right_side, top + lights_h),
                  ImVec2(right_side, height - lights_h));
  const ImVec2 viewport_pos(left + side, top);
  const ImVec2 viewport_size(std::max(main->Size.x - side - right_side, 1.0f), height);
  app.viewport.draw(app, viewport_pos, viewport_size);
  draw_inspector(app, viewport_pos, viewport_size);
  // The splitters go over the borders, after the panels so that they are on top.
  app.left_width +=
      splitter("##split-left", ImVec2(left + side - 3.0f, top), ImVec2(6.0f, height), true);
  app.right_width -=
      splitter("##split-right", ImVec2(right - right_side - 3.0f, top), ImVec2(6.0f, height), true);
  app.lights_share += splitter("##split-lights", ImVec2(right - right_side, top + lights_h - 3.0f),
                               ImVec2(right_side, 6.0f), false) /
                      height;
  draw_status_bar(app, ImVec2(left, top + height), ImVec2(main->Size.x, status_h));
  // The Quality window opens over the viewport's right side (its table needs more width than a
  // side panel has); it can be moved, resized and closed.
  const float quality_w = std::min(480.0f, viewport_size.x);
  draw_quality_panel(app, ImVec2(viewport_pos.x + viewport_size.x - quality_w, top),
                     ImVec2(quality_w, height));
  app.notices.draw(viewport_pos.x + viewport_size.x, top + height);
  std::string chosen;
  if (app.browser.draw(app.recent.of(recent_kind(app.browser.purpose)), chosen)) {
    browser_action(app, chosen);
  }
  draw_help_window(app);
  draw_recovery_modal(app);
  draw_quit_modal(app);
  draw_open_modal(app);
}

}  // namespace

void run_frame(App& app) {
  const double frame_start = app.now_s();
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  replay_key_taps(app);
  replay_script_mouse(app);
  ImGui::NewFrame();

  app.notices.expire(frame_start);
  // New threads (a renderer for the A/B view, exports) are lowered within a quarter second.
  if (frame_start - app.background_checked_s > 0.25) {
    app.background.update();
    app.background_checked_s = frame_start;
  }
  app.viewport.upload_frames(frame_start);
  app.swatches.poll();
  app.quality.poll();
  app.raster_quality.step(kRasterQualitySliceMs);  // GL: this thread owns the context
  poll_exports(app);
  if (app.script) {
    app.script->step(app);
    if (app.script->finished() && !app.quit) {
      app.script.reset();                     // the editor stays open
      app.script_mouse = App::ScriptMouse{};  // and the real mouse is the user's again
    }
  }
  handle_shortcuts(app);
  animate_light(app, frame_start);
  draw_layout(app);

  // A gesture (slider drag, viewport drag, animation) is one undo step; it ends here.
  if (!ImGui::IsAnyItemActive() && !app.viewport.gesture_active(frame_start) &&
      !app.view.orbit_light) {
    app.commands.seal();
  }
  app.viewport.sync(app.commands.scene(), app.commands.revision(), app.view,
                    app.snapshot ? &*app.snapshot : nullptr, frame_start);
  if (const std::string raster = app.viewport.take_raster_notice(); !raster.empty()) {
    app.notices.error(raster, frame_start);
  }
  // Once an edit's image has converged and is on screen the editor idles: the memory its passes
  // freed goes back to the system (a few ms, once per converged image).
  if (app.viewport.uploads() != app.released_at_upload &&
      app.viewport.converged_and_shown(app.commands.revision(), app.view)) {
    release_free_memory();
    app.released_at_upload = app.viewport.uploads();
  }
  if (app.autosaver) {
    // A failure is announced once when it appears or changes; the status bar keeps it on screen
    // (autosave_notice) until a write succeeds.
    app.autosaver->step(app.commands, app.selected_object, frame_start);
    const std::string& failure = app.autosaver->failure();
    if (!failure.empty() && failure != app.autosave_failure_shown) {
      app.notices.error("autosave failed: " + failure, frame_start);
    } else if (failure.empty() && !app.autosave_failure_shown.empty()) {
      app.notices.info("autosave works again", frame_start);
    }
    app.autosave_failure_shown = failure;
  }
  update_title(app);
  if (glfwWindowShouldClose(app.window)) {
    glfwSetWindowShouldClose(app.window, GLFW_FALSE);
    request_quit(app);
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
  if (app.capture.requested && app.capture.frames_to_skip-- <= 0) capture_window(app);
  glfwSwapBuffers(app.window);

  const double frame_end = app.now_s();
  app.viewport.frame_shown(frame_end);
  app.frame_times.add((frame_end - frame_start) * 1000.0);
  app.last_frame_s = frame_start;
}

double idle_timeout(const App& app) {
  const double now = app.now_s();
  if (app.capture.requested || app.viewport.gesture_active(now)) return 0.0;
  // Published frames wake the loop at once (glfwPostEmptyEvent); these short timeouts cover
  // what does not: the animation's next step (60 Hz), exports finishing, a script's next line.
  if (app.view.orbit_light) return 1.0 / 60.0;
  if (app.script || !app.exports.empty()) return 0.02;
  if (app.quality.running()) return 0.1;  // rows arrive and the elapsed time counts up
  // Raster rows are drawn a slice per frame; while the worker renders their references, the
  // progress only needs refreshing.
  if (app.raster_quality.state() == RasterTradeoff::State::rendering) return 0.0;
  if (app.raster_quality.running()) return 0.1;
  double timeout = 0.5;  // keeps hover states and the status bar fresh without spinning
  for (const Notice& n : app.notices.items) timeout = std::min(timeout, n.until_s - now);
  return std::max(timeout, 0.0);
}

}  // namespace gloss
