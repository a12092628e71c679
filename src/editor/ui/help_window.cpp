// The help window (F1): every keyboard shortcut (from the one table the keys are dispatched
// from, shortcuts.h), the mouse gestures and where the editor keeps its files. Rows wrap in the
// window's width, so no entry is cut off.
#include <algorithm>
#include <utility>
#include <vector>

#include <imgui.h>

#include "base/assets.h"
#include "editor/ui/panels/panels.h"
#include "editor/ui/parts/open_windows.h"
#include "editor/ui/parts/session.h"
#include "editor/ui/shortcuts.h"

namespace gloss {

namespace {

void row(const char* keys, const char* what) {
  ImGui::TableNextRow();
  ImGui::TableSetColumnIndex(0);
  ImGui::TextWrapped("%s", keys);
  ImGui::TableSetColumnIndex(1);
  ImGui::TextWrapped("%s", what);
}

// The mouse, in the viewport and on the panels.
struct Gesture {
  const char* what_you_do;
  const char* effect;
};
constexpr Gesture kGestures[] = {
    {"left drag", "orbit the camera about its target"},
    {"right or middle drag, Shift + left drag", "pan"},
    {"mouse wheel", "zoom"},
    {"left click", "select the object under the cursor"},
    {"drag a gizmo handle (Ctrl: snap)", "move, rotate or scale the selected objects"},
    {"Ctrl+click, Shift+click an Outliner row", "add to the selection, select a range"},
    {"drag a light marker", "move the light in the plane facing you"},
    {"drag an edge arrow", "bring a light out of view under the cursor, at the target's depth"},
    {"drag a panel's inner edge", "resize the side panels (the cursor shows the arrows)"},
    {"click a collapsed panel's strip", "expand it again"},
    {"Ctrl+click a slider", "type an exact value"},
};

// A table of keys and what they do, its first column as wide as its widest entry.
template <class Rows>
void key_table(const char* id, const char* first_header, const Rows& rows) {
  float keys_width = ImGui::CalcTextSize(first_header).x;
  for (const auto& r : rows) keys_width = std::max(keys_width, ImGui::CalcTextSize(r.first).x);
  keys_width = std::min(keys_width, ImGui::GetContentRegionAvail().x * 0.45f);
  const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV;
  if (!ImGui::BeginTable(id, 2, flags)) return;
  ImGui::TableSetupColumn(first_header, ImGuiTableColumnFlags_WidthFixed, keys_width);
  ImGui::TableSetupColumn("does", ImGuiTableColumnFlags_WidthStretch);
  ImGui::TableHeadersRow();
  for (const auto& r : rows) row(r.first, r.second);
  ImGui::EndTable();
}

}  // namespace

void draw_help_window(OpenWindows& windows, const Session& session) {
  if (!windows.help) return;
  // Never larger than the window: a small window scrolls the help instead of cutting it off.
  const ImVec2 display = ImGui::GetMainViewport()->Size;
  ImGui::SetNextWindowSize(
      ImVec2(std::min(600.0f, display.x - 40.0f), std::min(620.0f, display.y - 60.0f)),
      ImGuiCond_FirstUseEver);
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
  std::vector<std::pair<const char*, const char*>> keys;
  for (const Shortcut& k : shortcuts()) {
    if (k.keys[0] != '\0') keys.emplace_back(k.keys, k.what);  // "" shares the line above
  }
  key_table("##keys", "key", keys);
  ImGui::Spacing();
  std::vector<std::pair<const char*, const char*>> mouse;
  for (const Gesture& g : kGestures) mouse.emplace_back(g.what_you_do, g.effect);
  key_table("##mouse", "mouse", mouse);
  ImGui::TextWrapped("Keys act unless a text field has the keyboard (Ctrl+Z there undoes typing).");
  ImGui::Spacing();
  // The GLSL path (issue 12): docs/editor.md, "Raster (GLSL) path".
  ImGui::TextUnformatted("Renderer (View & Quality panel)");
  for (const char* line :
       {"Ray traced: exact, refined to the scene's spp",
        "Raster (GLSL): one sample per pixel, hard shadows from shadow maps",
        "Automatic: raster during drags if measured no slower, ray traced when still",
        "Per vertex (Gouraud) against per pixel: lower the teapot tessellation to see it break",
        "A/B: ray traced | raster, per pixel | per vertex, with the heat map"}) {
    ImGui::Bullet();
    ImGui::TextWrapped("%s", line);
  }
  ImGui::TextWrapped(
      "Scripts: renderer cpu|gl|auto, shading pixel|vertex, shadow-map SIZE (16..4096), "
      "shadow-bias TEXELS (>= 0), tessellation N (1..64), view ab cpu-gl|pixel-vertex");
  ImGui::Spacing();
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
  ImGui::TextWrapped("Layout and recent files: %s", session.config_folder.string().c_str());
  if (session.autosaver) {
    ImGui::TextWrapped("Crash recovery file: %s", session.autosaver->file().string().c_str());
  }
  ImGui::PopStyleColor();
  ImGui::End();
}

}  // namespace gloss
