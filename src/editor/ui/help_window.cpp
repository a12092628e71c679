// The help window (F1): shortcuts, mouse gestures and where the editor keeps its files.
#include <imgui.h>

#include "base/assets.h"
#include "editor/ui/panels/panels.h"
#include "editor/ui/parts/open_windows.h"
#include "editor/ui/parts/session.h"

namespace gloss {

namespace {

void row(const char* keys, const char* what) {
  ImGui::TableNextRow();
  ImGui::TableSetColumnIndex(0);
  ImGui::TextUnformatted(keys);
  ImGui::TableSetColumnIndex(1);
  ImGui::TextUnformatted(what);
}

}  // namespace

void draw_help_window(OpenWindows& windows, const Session& session) {
  if (!windows.help) return;
  ImGui::SetNextWindowSize(ImVec2(560, 520), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_FirstUseEver,
                          ImVec2(0.5f, 0.5f));
  if (!ImGui::Begin("Help", &windows.help)) {
    ImGui::End();
    return;
  }
  ImGui::TextWrapped(
      "gloss edits Phong materials live: the viewport shows the CPU ray tracer's image, "
      "refined pass by pass, or the same scene drawn by OpenGL shaders (Renderer, below). "
      "Every edit can be undone. The full guide: %s",
      doc_path("editor.md").c_str());
  if (ImGui::BeginTable("##keys", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV)) {
    ImGui::TableSetupColumn("keys", ImGuiTableColumnFlags_WidthFixed, 240.0f);
    ImGui::TableSetupColumn("action");
    row("F1", "show or hide this help");
    row("Ctrl+Z", "undo");
    row("Ctrl+Shift+Z, Ctrl+Y", "redo");
    row("Ctrl+S", "screenshot (kind chosen in View & Quality)");
    row("Ctrl+Shift+S", "save the scene");
    row("Ctrl+O", "open a scene");
    row("Ctrl+Q", "quit");
    row("1 / 2 / 3 / 4", "render / terms 2x2 / one term / A/B view");
    row("Ctrl+B", "snapshot: A/B of the scene now (A) against later edits (B)");
    row("Esc", "close a menu, this help, the file panel");
    row("left drag", "orbit the camera about its target");
    row("right or middle drag, Shift+left", "pan");
    row("mouse wheel", "zoom");
    row("left click", "select the object under the cursor");
    row("drag a light marker", "move the light in the plane facing you");
    row("click an edge arrow", "select a light that is out of view");
    row("drag a panel's inner edge", "resize the side panels");
    row("Ctrl+click a slider", "type an exact value");
    ImGui::EndTable();
  }
  ImGui::Spacing();
  // The GLSL path (issue 12): docs/editor.md, "Raster (GLSL) path".
  ImGui::TextUnformatted("Renderer (View & Quality panel)");
  ImGui::BulletText("Ray traced: exact, refined to the scene's spp");
  ImGui::BulletText("Raster (GLSL): one sample per pixel, hard shadows from shadow maps");
  ImGui::BulletText("Automatic: raster during drags if measured no slower, ray traced when still");
  ImGui::BulletText(
      "Per vertex (Gouraud) against per pixel: lower the teapot tessellation to see it break");
  ImGui::BulletText("A/B: ray traced | raster, per pixel | per vertex, with the heat map");
  ImGui::TextWrapped(
      "Scripts: renderer cpu|gl|auto, shading pixel|vertex, shadow-map SIZE (16..4096), "
      "shadow-bias TEXELS (>= 0), tessellation N (1..64), view ab cpu-gl|pixel-vertex");
  ImGui::Spacing();
  ImGui::TextDisabled("Layout and recent files: %s", session.config_folder.string().c_str());
  if (session.autosaver) {
    ImGui::TextDisabled("Crash recovery file: %s", session.autosaver->file().string().c_str());
  }
  ImGui::End();
}

}  // namespace gloss
