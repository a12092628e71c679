#include "editor/ui/file_browser.h"

#include <algorithm>
#include <system_error>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "base/text/ascii.h"
#include "editor/model/session/file_defaults.h"
#include "io/model/model_loader.h"

namespace gloss {

const char* title(BrowsePurpose purpose) {
  switch (purpose) {
    case BrowsePurpose::open_scene:
      return "Open scene";
    case BrowsePurpose::add_model:
      return "Add model";
    case BrowsePurpose::load_materials:
      return "Load materials";
    case BrowsePurpose::save_scene:
      return "Save scene as";
    case BrowsePurpose::save_materials:
      return "Save all materials";
    case BrowsePurpose::save_material:
      return "Save the selected material";
    case BrowsePurpose::export_glsl:
      return "Export GLSL";
    case BrowsePurpose::export_gltf:
      return "Export glTF";
    case BrowsePurpose::open_environment:
      return "Environment map";
    case BrowsePurpose::load_map:
      return "Load map";
  }
  return "File";
}

bool is_save(BrowsePurpose purpose) {
  return purpose == BrowsePurpose::save_scene || purpose == BrowsePurpose::save_materials ||
         purpose == BrowsePurpose::save_material || purpose == BrowsePurpose::export_glsl ||
         purpose == BrowsePurpose::export_gltf;
}

std::vector<std::string> extensions(BrowsePurpose purpose) {
  switch (purpose) {
    case BrowsePurpose::open_scene:
      return {".json", ".png"};  // a PNG gloss wrote carries its scene
    case BrowsePurpose::save_scene:
      return {".json"};
    case BrowsePurpose::add_model:
      return model_extensions();
    case BrowsePurpose::load_materials:
    case BrowsePurpose::save_materials:
    case BrowsePurpose::save_material:
      return {".json", ".mtl"};
    case BrowsePurpose::export_glsl:
      return {".frag", ".glsl"};
    case BrowsePurpose::export_gltf:
      return {".glb", ".gltf"};
    case BrowsePurpose::open_environment:
      return {".hdr", ".exr", ".png"};
    case BrowsePurpose::load_map:
      return {".png", ".jpg", ".jpeg", ".exr", ".hdr"};
  }
  return {};
}

RecentKind recent_kind(BrowsePurpose purpose) {
  switch (purpose) {
    case BrowsePurpose::add_model:
    case BrowsePurpose::open_environment:  // files added to a scene (the list is not extended)
      return RecentKind::model;
    case BrowsePurpose::load_materials:
    case BrowsePurpose::save_materials:
    case BrowsePurpose::save_material:
      return RecentKind::materials;
    case BrowsePurpose::load_map:
      return RecentKind::maps;
    case BrowsePurpose::open_scene:
    case BrowsePurpose::save_scene:
    case BrowsePurpose::export_glsl:
    case BrowsePurpose::export_gltf:
      break;
  }
  return RecentKind::scene;
}

namespace {}  // namespace

std::filesystem::path scene_folder(const std::string& scene_path, const std::string& fallback) {
  return scene_path.empty() ? std::filesystem::path(fallback)
                            : std::filesystem::path(scene_path).parent_path();
}

void FileBrowser::show(BrowsePurpose what, const std::filesystem::path& start_folder,
                       const std::string& suggested_name) {
  open = true;
  purpose = what;
  std::error_code ec;
  folder = std::filesystem::is_directory(start_folder, ec) ? start_folder
                                                           : std::filesystem::current_path(ec);
  folder = std::filesystem::absolute(folder, ec).lexically_normal();
  name = suggested_name;
  error.clear();
  confirm_replace.clear();
  stale = true;
  focus_name = true;
}

void FileBrowser::start(BrowsePurpose what, const std::string& scene_path,
                        const std::string& suggested_name) {
  show(what, is_save(what) ? save_folder(last_folder) : open_folder(last_folder, scene_path),
       suggested_name);
}

void FileBrowser::refresh() {
  entries.clear();
  stale = false;
  const std::vector<std::string> wanted = extensions(purpose);
  std::error_code ec;
  for (const auto& item : std::filesystem::directory_iterator(folder, ec)) {
    const std::string file = item.path().filename().string();
    if (file.empty() || file[0] == '.') continue;  // hidden files and temporaries
    std::error_code type_error;
    const bool is_folder = item.is_directory(type_error);
    if (!is_folder && !show_all &&
        std::find(wanted.begin(), wanted.end(), lower_extension(item.path())) == wanted.end()) {
      continue;
    }
    entries.push_back({file, is_folder});
  }
  if (ec) error = "cannot list " + folder.string() + ": " + ec.message();
  std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
    return a.folder != b.folder ? a.folder : a.name < b.name;
  });
}

std::string FileBrowser::resolved() const {
  std::filesystem::path path(name);
  if (path.is_relative()) path = folder / path;
  if (is_save(purpose) && path.extension().empty()) path += extensions(purpose).front();
  return path.lexically_normal().string();
}

bool FileBrowser::confirm(std::string& chosen) {
  if (name.empty()) {
    error = "type a file name or pick a file";
    return false;
  }
  const std::string path = resolved();
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    folder = path;
    name.clear();
    stale = true;
    return false;
  }
  if (is_save(purpose) && is_shipped_path(path)) {
    error = path + " is a file gloss ships: save your own copy in another folder";
    return false;
  }
  if (is_save(purpose) && std::filesystem::exists(path, ec) && confirm_replace != path) {
    confirm_replace = path;
    error = path + " exists: press Save again to replace it";
    return false;
  }
  chosen = path;
  last_folder = std::filesystem::path(path).parent_path();
  return true;
}

bool FileBrowser::draw(const RecentFiles& recent, std::string& chosen) {
  if (!open) return false;
  if (stale) refresh();
  ImGui::SetNextWindowSize(ImVec2(640, 440), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_FirstUseEver,
                          ImVec2(0.5f, 0.5f));
  const std::string window_title = std::string(title(purpose)) + "###file-browser";
  if (!ImGui::Begin(window_title.c_str(), &open)) {
    ImGui::End();
    return false;
  }
  bool done = false;
  if (ImGui::Button("Up") && folder.has_parent_path()) {
    folder = folder.parent_path();
    stale = true;
  }
  ImGui::SameLine();
  // The folder's path, its start cut ("...") where it would run under the checkbox.
  const float room = ImGui::GetWindowWidth() - 160.0f - ImGui::GetCursorPosX();
  std::string shown = folder.string();
  while (shown.size() > 4 && ImGui::CalcTextSize(shown.c_str()).x > room) {
    shown = "..." + shown.substr(std::min<std::size_t>(shown.size(), 8));
  }
  ImGui::TextUnformatted(shown.c_str());
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", folder.string().c_str());
  ImGui::SameLine(ImGui::GetWindowWidth() - 150.0f);
  if (ImGui::Checkbox("all files", &show_all)) stale = true;

  const float footer = ImGui::GetFrameHeightWithSpacing() * 2.0f + 8.0f;
  const float recent_width = recent.paths.empty() || is_save(purpose) ? 0.0f : 220.0f;
  ImGui::BeginChild("##entries", ImVec2(-recent_width - (recent_width > 0 ? 8.0f : 0.0f), -footer),
                    true);
  for (const Entry& entry : entries) {
    const std::string label = entry.folder ? "[dir] " + entry.name : entry.name;
    if (ImGui::Selectable(label.c_str(), !entry.folder && entry.name == name,
                          ImGuiSelectableFlags_AllowDoubleClick)) {
      if (entry.folder) {
        if (ImGui::IsMouseDoubleClicked(0)) {
          folder /= entry.name;
          stale = true;
        }
      } else {
        name = entry.name;
        error.clear();
        if (ImGui::IsMouseDoubleClicked(0)) done = confirm(chosen);
      }
    }
  }
  ImGui::EndChild();
  if (recent_width > 0.0f) {
    ImGui::SameLine();
    ImGui::BeginChild("##recent", ImVec2(recent_width, -footer), true);
    ImGui::TextDisabled("Recent");
    for (const std::string& path : recent.paths) {
      const std::string label = std::filesystem::path(path).filename().string() + "##" + path;
      if (ImGui::Selectable(label.c_str())) {
        name = path;
        done = confirm(chosen);
      }
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", path.c_str());
    }
    ImGui::EndChild();
  }
  ImGui::SetNextItemWidth(-170.0f);
  if (focus_name) {
    ImGui::SetKeyboardFocusHere();
    focus_name = false;
  }
  if (ImGui::InputText("##path", &name, ImGuiInputTextFlags_EnterReturnsTrue)) {
    done = confirm(chosen);
  }
  ImGui::SameLine();
  if (ImGui::Button(is_save(purpose) ? "Save" : "Open", ImVec2(75, 0))) done = confirm(chosen);
  ImGui::SameLine();
  if (ImGui::Button("Cancel", ImVec2(75, 0))) open = false;
  if (!error.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
    ImGui::TextWrapped("%s", error.c_str());
    ImGui::PopStyleColor();
  } else {
    ImGui::TextDisabled("Double-click a folder to enter it; type a full path to go anywhere.");
  }
  ImGui::End();
  return done;
}

}  // namespace gloss
